// Output/Time interval: output in every time step that reaches a multiple
// of the interval, besides step 0 and the end. With Time interval = 0.01:
//  - dt = 3e-3 to the end time 0.05 (17 steps, the last one 2e-3 long):
//    the steps ending at 0.012, 0.021, 0.030, 0.042 and 0.05, so steps 0,
//    4, 7, 10, 14 and 17;
//  - dt = 1e-3 (sums of steps miss 0.01 by round-off either way): every
//    tenth step, 0, 10, ..., 50;
//  - together with Interval = 5 and dt = 3e-3: the union, 0, 4, 5, 7, 10,
//    14, 15 and 17 (10 is both).

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

std::vector<unsigned int>
output_steps(const std::string &time_step, const std::string &interval)
{
  auto                      simulator = make_simulator<2>("",
                                     R"(
set Dimension = 2
set Problem = custom
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 2, 2
end
subsection Material
  set Young's modulus = 1
  set Density = 1
end
subsection Time
  set End time = 0.05
  set Time step = )" + time_step + R"(
end
subsection Output
  set Time interval = 0.01
  set Interval = )" + interval + R"(
end
)",
                                     "output-time-interval");
  std::vector<unsigned int> steps;
  simulator->run([&](const unsigned int step, const Statistics<2> &) {
    steps.push_back(step);
  });
  return steps;
}

void
expect(const std::string               &time_step,
       const std::string               &interval,
       const std::vector<unsigned int> &expected)
{
  const auto  steps = output_steps(time_step, interval);
  std::string list;
  for (const unsigned int step : steps)
    list += (list.empty() ? "" : ", ") + std::to_string(step);
  check(steps == expected,
        "dt = " + time_step + ", Interval = " + interval +
          ": output at steps " + list);
  deallog << "dt = " << time_step << ", Interval = " << interval
          << ": output at steps " << list << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  expect("3e-3", "0", {0, 4, 7, 10, 14, 17});
  expect("1e-3", "0", {0, 10, 20, 30, 40, 50});
  expect("3e-3", "5", {0, 4, 5, 7, 10, 14, 15, 17});
}
