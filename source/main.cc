#include <deal.II/base/mpi.h>

#include <mpm_otm/simulator/simulator.h>

#include <iostream>

namespace
{
  /**
   * Read @p filename (empty: the defaults, i.e. the default benchmark) and
   * run the simulation in @p dim dimensions.
   */
  template <int dim>
  void
  run(const std::string &filename)
  {
    dealii::ParameterHandler prm;
    MpmOtm::Simulator<dim>::declare_parameters(prm);
    if (!filename.empty())
      prm.parse_input(filename);
    MpmOtm::Simulator<dim> simulator(MPI_COMM_WORLD, std::cout);
    simulator.parse_parameters(prm);
    simulator.setup(prm);
    simulator.run();
  }
} // namespace



int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      const std::string argument = (argc > 1) ? argv[1] : "";
      if (argument == "--help" || argument == "-h")
        {
          if (root)
            std::cout << "Usage: mpm-otm [parameter file]\n"
                      << "       mpm-otm --print-parameters DIM\n"
                      << "Without a file the default benchmark (B1b, 1D "
                         "vibrating bar, MPM) runs.\n";
          return 0;
        }
      if (argument == "--print-parameters")
        {
          const int                dim = (argc > 2) ? std::atoi(argv[2]) : 2;
          dealii::ParameterHandler prm;
          if (dim == 1)
            MpmOtm::Simulator<1>::declare_parameters(prm);
          else if (dim == 3)
            MpmOtm::Simulator<3>::declare_parameters(prm);
          else
            MpmOtm::Simulator<2>::declare_parameters(prm);
          if (root)
            prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
          return 0;
        }

      switch (MpmOtm::read_dimension(argument))
        {
          case 1:
            run<1>(argument);
            break;
          case 2:
            run<2>(argument);
            break;
          default:
            run<3>(argument);
            break;
        }
    }
  catch (const dealii::ExceptionBase &error)
    {
      if (root)
        {
          std::cerr << "\nmpm-otm stopped with an error:\n";
          error.print_info(std::cerr);
          std::cerr << std::endl;
        }
      return 1;
    }
  catch (const std::exception &error)
    {
      if (root)
        std::cerr << "\nmpm-otm stopped with an error:\n"
                  << error.what() << std::endl;
      return 1;
    }
  return 0;
}
