/*
 * pcl_ext: counter-based random numbers for the scanner simulator.
 */
#pragma once

#include <pcl_ext/common/random.h>

namespace pcl_ext {
namespace simulation {
/** \brief The simulator's random numbers are the library's (pcl_ext/common/random.h):
 * each ray of a scan seeds one stream from (seed, scanner, ray index), which makes the
 * output independent of the thread count and of the order in which rays are processed.
 */
using pcl_ext::hashCombine;
using pcl_ext::RandomStream;
using pcl_ext::splitMix64;
} // namespace simulation
} // namespace pcl_ext
