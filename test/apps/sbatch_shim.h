/*
 * A stand-in for Slurm's sbatch in the tests of scripts/tiles_slurm.sh: it runs each
 * job at once (every task of an array in turn), logs "array=<range|none> <command>" per
 * job, and prints a job id.
 */
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pcl_ext {
namespace test {
/** Write the stand-in as \a folder/sbatch (put \a folder first on the PATH). */
inline void
writeSbatchShim (const std::string& folder)
{
  std::filesystem::create_directories (folder);
  {
    std::ofstream sbatch (folder + "/sbatch");
    sbatch
        << "#!/bin/bash\n"
           "array=''; wrap=''\n"
           "for a in \"$@\"; do case \"$a\" in --array=*) array=\"${a#--array=}\";; "
           "--wrap=*) wrap=\"${a#--wrap=}\";; esac; done\n"
           "echo \"array=${array:-none} ${wrap%% -workdir*}\" >> \"$(dirname "
           "\"$0\")/sbatch.log\"\n"
           "if [ -n \"$array\" ]; then\n"
           "  for i in $(seq \"${array%-*}\" \"${array#*-}\"); do\n"
           "    SLURM_ARRAY_TASK_ID=$i bash -c \"$wrap\" > /dev/null 2>&1 || exit 1\n"
           "  done\n"
           "else bash -c \"$wrap\" > /dev/null 2>&1 || exit 1; fi\n"
           "echo 4242\n";
  }
  std::filesystem::permissions (folder + "/sbatch", std::filesystem::perms::owner_all);
}

/** The jobs the stand-in in \a folder ran, one line each. */
inline std::vector<std::string>
sbatchJobs (const std::string& folder)
{
  std::ifstream log (folder + "/sbatch.log");
  std::vector<std::string> jobs;
  for (std::string line; std::getline (log, line);)
    jobs.push_back (line);
  return jobs;
}
} // namespace test
} // namespace pcl_ext
