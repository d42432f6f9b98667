/*
 * pcl_ext_compare_segmenters: running one method in a child process, to measure its
 * time and its own peak memory.
 */
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace pcl_ext {
namespace compare {
/** \brief What a run in a child process reports. */
struct IsolatedRun {
  bool ok = false;      ///< the work returned true and its result arrived
  std::string error;    ///< why not, when !ok
  double seconds = 0.0; ///< wall time of the work, measured in the child
  std::size_t peak_bytes =
      0; ///< peak resident memory of the work above what the child started with
  std::vector<char> result; ///< the bytes the result function produced
};

/** \brief Run \a work in a forked child process and return its time, peak memory and
 * result.
 *
 * Peak memory: the child starts as a copy of this process, so everything loaded before
 * (the cloud, the normals) is resident in it already. The child resets its high-water
 * mark
 * (`/proc/self/clear_refs`, "5"), reads its resident set (VmRSS), runs \a work, and
 * reports the high-water mark (VmHWM) minus that resident set: the memory the work
 * itself needed at its peak, whatever ran before in this process. Free heap memory is
 * returned to the system (malloc_trim) before the fork, so that the child cannot reuse
 * memory that is already resident and hide its own allocations.
 *
 * Time: wall-clock time of \a work alone. \a result runs after both measurements and
 * turns the work's output into bytes, which come back through a pipe.
 *
 * A child that crashes, exits, returns false or runs longer than \a timeout_seconds (>
 * 0; it is then killed) gives ok = false with the reason. Only the calling thread
 * exists in the child, so the child may use OpenMP even when this process never should
 * have: callers keep OpenMP out of this process (GNU libgomp does not survive a fork
 * after it started threads).
 */
IsolatedRun
runIsolated (const std::function<bool()>& work,
             const std::function<std::vector<char>()>& result,
             double timeout_seconds = 0.0);

/** \brief Append the bytes of a vector of trivially copyable values to \a bytes. */
template <typename T>
void
appendBytes (const std::vector<T>& values, std::vector<char>& bytes)
{
  const char* begin = reinterpret_cast<const char*> (values.data());
  bytes.insert (bytes.end(), begin, begin + values.size() * sizeof (T));
}

/** \brief Read \a count values of type T from \a bytes at \a offset (advanced); false
 * when \a bytes is too short. */
template <typename T>
bool
readBytes (const std::vector<char>& bytes,
           std::size_t& offset,
           std::size_t count,
           std::vector<T>& values)
{
  if (offset > bytes.size() || (bytes.size() - offset) / sizeof (T) < count)
    return false;
  values.resize (count);
  std::copy (bytes.begin() + offset,
             bytes.begin() + offset + count * sizeof (T),
             reinterpret_cast<char*> (values.data()));
  offset += count * sizeof (T);
  return true;
}
} // namespace compare
} // namespace pcl_ext
