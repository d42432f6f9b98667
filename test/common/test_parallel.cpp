/*
 * Tests of the thread-count convention: 0 means all cores, as in PCL's OpenMP classes.
 */
#include <pcl_ext/common/parallel.h>

#include <gtest/gtest.h>

#ifdef _OPENMP
#include <omp.h>
#endif

TEST (Parallel, ZeroMeansAllCoresOtherCountsAreKept)
{
#ifdef _OPENMP
  EXPECT_EQ (pcl_ext::resolveThreadCount (0),
             static_cast<unsigned int> (omp_get_num_procs()));
  EXPECT_GE (pcl_ext::resolveThreadCount (0), 1u);
  EXPECT_EQ (pcl_ext::resolveThreadCount (1), 1u);
  EXPECT_EQ (pcl_ext::resolveThreadCount (3), 3u);
  // More threads than cores are what was asked for, not capped.
  const unsigned int many = static_cast<unsigned int> (omp_get_num_procs()) + 5;
  EXPECT_EQ (pcl_ext::resolveThreadCount (many), many);
#else
  // Without OpenMP every class runs on one thread.
  EXPECT_EQ (pcl_ext::resolveThreadCount (0), 1u);
  EXPECT_EQ (pcl_ext::resolveThreadCount (3), 1u);
#endif
}
