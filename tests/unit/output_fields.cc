// The VTU files carry the fields the manual promises a ParaView user: the
// particles' displacement and velocity as vectors, the three-dimensional
// stress (with sigma_zz of plane strain in its place) and logarithmic strain
// as 3 x 3 tensors, the mean, von Mises and principal stresses,
// plastic_strain, det_F and material; the grid's nodal_mass and
// nodal_velocity as a vector. Vectors are written with 3 components in 2D
// (VTU pads them). The values themselves: unit/stress_output.

#include <fstream>
#include <iterator>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

const std::string parameters = R"(
set Dimension = 2
set Problem = custom
subsection Time
  set End time = 1e-4
  set Time step = 1e-4
end
subsection Mesh
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 2, 2
end
subsection Material
  set Model = von Mises
  set Young's modulus = 1e6
  set Density = 1
  subsection von Mises
    set Yield stress = 1e3
  end
end
subsection Output
  set Directory = output-fields
  set Overwrite = true
  set Format = vtu
end
)";

std::string
read(const std::string &name)
{
  std::ifstream file("output-fields/" + name);
  check(static_cast<bool>(file), name + " was not written");
  return std::string((std::istreambuf_iterator<char>(file)),
                     std::istreambuf_iterator<char>());
}

void
expect_field(const std::string &file,
             const std::string &text,
             const std::string &name,
             const unsigned int n_components)
{
  // VTU names the components of vectors and tensors only.
  const std::string tag =
    "Name=\"" + name + "\" " +
    (n_components == 1 ?
       std::string("format") :
       "NumberOfComponents=\"" + std::to_string(n_components) + "\"");
  check(text.find(tag) != std::string::npos,
        file + " must hold " + name + " with " + std::to_string(n_components) +
          " components");
  deallog << file << ": " << name << ", " << n_components << " components"
          << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  simulator_from_text<2>(parameters)->run();
  const std::string particles = read("particles_00001.0.vtu");
  expect_field("particles", particles, "displacement", 3);
  expect_field("particles", particles, "velocity", 3);
  expect_field("particles", particles, "stress", 9);
  expect_field("particles", particles, "log_strain", 9);
  for (const std::string name : {"mean_stress",
                                 "von_mises_stress",
                                 "principal_stress_1",
                                 "principal_stress_2",
                                 "principal_stress_3",
                                 "plastic_strain",
                                 "det_F",
                                 "material"})
    expect_field("particles", particles, name, 1);
  const std::string grid = read("grid_00001.0.vtu");
  expect_field("grid", grid, "nodal_mass", 1);
  expect_field("grid", grid, "nodal_velocity", 3);
}
