#include <deal.II/base/mpi.h>

#include <mpm_otm/simulator/simulator.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

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
    std::string text;
    if (!filename.empty())
      {
        std::ifstream     file(filename);
        std::stringstream contents;
        contents << file.rdbuf();
        text = contents.str();
      }
    dealii::ParameterHandler prm;
    MpmOtm::Simulator<dim>::declare_parameters(prm,
                                               MpmOtm::SubsectionNames::read(
                                                 text));
    if (!filename.empty())
      prm.parse_input(filename);
    MpmOtm::Simulator<dim> simulator(MPI_COMM_WORLD, std::cout);
    simulator.parse_parameters(prm);
    simulator.setup(prm);
    simulator.run();
  }



  /**
   * Report @p message and return the exit status. Serial runs just print it.
   * In parallel, the errors of the application are raised on every rank at
   * once (rank 0 prints them), but an error of one rank alone would leave
   * the others waiting in a collective operation for ever. So rank 0 prints
   * and aborts all ranks; any other rank first gives rank 0 the time to do
   * so for the same error, and if it is still running, the error was its
   * own: it prints it with its rank and aborts all ranks.
   */
  int
  stop_with_error(const std::string &message)
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (rank != 0)
      std::this_thread::sleep_for(std::chrono::seconds(3));
    std::cerr << "\nmpm-otm stopped with an error";
    if (rank != 0)
      std::cerr << " on MPI rank " << rank;
    std::cerr << ":\n" << message << std::endl;
    if (n_ranks > 1)
      MPI_Abort(MPI_COMM_WORLD, 1);
    return 1;
  }
} // namespace



int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  bool        failed = false;
  std::string error_message;
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
          const int dim = (argc > 2) ? std::atoi(argv[2]) : 2;
          // One subsection of each named kind, called "example", stands for
          // those the entries Materials, Bodies and Boundaries name.
          MpmOtm::SubsectionNames examples;
          examples.materials  = {"example"};
          examples.bodies     = {"example"};
          examples.boundaries = {"example"};
          dealii::ParameterHandler prm;
          if (dim == 1)
            MpmOtm::Simulator<1>::declare_parameters(prm, examples);
          else if (dim == 3)
            MpmOtm::Simulator<3>::declare_parameters(prm, examples);
          else
            MpmOtm::Simulator<2>::declare_parameters(prm, examples);
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
      std::ostringstream text;
      error.print_info(text);
      failed        = true;
      error_message = text.str();
    }
  catch (const std::exception &error)
    {
      failed        = true;
      error_message = error.what();
    }
  return failed ? stop_with_error(error_message) : 0;
}
