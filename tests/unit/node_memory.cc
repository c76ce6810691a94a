// The memory limit of a batch job's control group, which the checks before
// large allocations respect besides MemAvailable (NodeMemory,
// manual "Safety"): NodeMemory::control_group_headroom() on cgroup trees
// written here by hand, with the headroom (limit less usage) computed by
// hand.
//
// 1. cgroup v1: the job's group has a limit of 4e9 bytes and uses 1e9;
//    its parent and the root have none (2^63 rounded to a page): 3e9.
// 2. The same, with a parent limited to 2e9 and using 1.5e9: 5e8, from the
//    parent.
// 3. cgroup v2 (cgroup.controllers at the mount): the group says "max",
//    its parent 8e9 with 6e9 in use: 2e9.
// 4. cgroup v2 beside v1 (mounted at unified/), limit 5e9, usage 1e9: 4e9.
// 5. A group that is not visible under the mount (a container's namespace)
//    is the mount's root: 1e9 limit, 2.5e8 used: 7.5e8.
// 6. No limit anywhere: infinity.

#include <mpm_otm/base/node_memory.h>

#include <filesystem>
#include <fstream>

#include "../tests.h"

using namespace MpmOtm;
using namespace MpmOtmTests;

namespace
{
  namespace fs = std::filesystem;

  void
  write(const std::string &file, const std::string &contents)
  {
    fs::create_directories(fs::path(file).parent_path());
    std::ofstream(file) << contents << "\n";
  }

  void
  report(const std::string &name,
         const std::string &root,
         const double       expected,
         const std::string &expected_file)
  {
    std::string  file;
    const double headroom =
      NodeMemory::control_group_headroom(root + "/cgroup", root, file);
    if (file.rfind(root, 0) == 0)
      file = file.substr(root.size());
    deallog << name << ": headroom " << headroom << " bytes, limit "
            << (file.empty() ? "none" : file) << std::endl;
    check(headroom == expected && file == expected_file,
          name + ": expected " + std::to_string(expected) + " from <" +
            expected_file + ">");
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string none = "9223372036854771712";
  fs::remove_all("groups");

  write("groups/v1/cgroup",
        "5:cpu,cpuacct:/slurm/job_7\n4:memory:/slurm/job_7");
  write("groups/v1/memory/slurm/job_7/memory.limit_in_bytes", "4000000000");
  write("groups/v1/memory/slurm/job_7/memory.usage_in_bytes", "1000000000");
  write("groups/v1/memory/slurm/memory.limit_in_bytes", none);
  write("groups/v1/memory/slurm/memory.usage_in_bytes", "1500000000");
  write("groups/v1/memory/memory.limit_in_bytes", none);
  report("v1, the job's group",
         "groups/v1",
         3e9,
         "/memory/slurm/job_7/memory.limit_in_bytes");
  write("groups/v1/memory/slurm/memory.limit_in_bytes", "2000000000");
  report("v1, a parent tighter",
         "groups/v1",
         5e8,
         "/memory/slurm/memory.limit_in_bytes");

  write("groups/v2/cgroup", "0::/user.slice/job");
  write("groups/v2/cgroup.controllers", "cpu memory");
  write("groups/v2/user.slice/job/memory.max", "max");
  write("groups/v2/user.slice/job/memory.current", "100");
  write("groups/v2/user.slice/memory.max", "8000000000");
  write("groups/v2/user.slice/memory.current", "6000000000");
  report("v2", "groups/v2", 2e9, "/user.slice/memory.max");

  write("groups/hybrid/cgroup", "1:name=systemd:/job\n0::/job");
  write("groups/hybrid/unified/job/memory.max", "5000000000");
  write("groups/hybrid/unified/job/memory.current", "1000000000");
  report("v2 beside v1", "groups/hybrid", 4e9, "/unified/job/memory.max");

  write("groups/namespace/cgroup", "4:memory:/outside/the/container");
  write("groups/namespace/memory/memory.limit_in_bytes", "1000000000");
  write("groups/namespace/memory/memory.usage_in_bytes", "250000000");
  report("a group outside the mount",
         "groups/namespace",
         7.5e8,
         "/memory/memory.limit_in_bytes");

  write("groups/unlimited/cgroup", "4:memory:/job\n0::/job");
  write("groups/unlimited/memory/job/memory.limit_in_bytes", none);
  write("groups/unlimited/unified/job/memory.max", "max");
  report("no limit",
         "groups/unlimited",
         std::numeric_limits<double>::infinity(),
         "");
}
