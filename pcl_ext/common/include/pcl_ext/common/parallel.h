/*
 * pcl_ext: thread-count convention shared by every parallel class.
 */
#pragma once

#ifdef _OPENMP
#include <omp.h>
#endif

namespace pcl_ext {
/** \brief Threads to use for a requested count: 0 means all cores, as in PCL's OMP
 * classes. */
inline unsigned int
resolveThreadCount (unsigned int requested)
{
#ifdef _OPENMP
  if (requested == 0)
    return static_cast<unsigned int> (omp_get_num_procs());
  return requested;
#else
  (void)requested;
  return 1;
#endif
}
} // namespace pcl_ext
