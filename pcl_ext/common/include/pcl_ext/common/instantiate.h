/*
 * pcl_ext: explicit instantiation of precompiled classes for the common point types.
 */
#pragma once

#include <pcl/point_types.h>

#include <boost/preprocessor/cat.hpp>
#include <boost/preprocessor/seq/for_each.hpp>

/** \brief XYZ point types that src/ files instantiate precompiled classes for. Other
 * types work through PCL_NO_PRECOMPILE, which makes the headers include their
 * implementations. A build can give its own list (CMake option PCL_EXT_POINT_TYPES,
 * which defines this macro for the libraries' sources): each type costs compile time in
 * every src/ file. */
#ifndef PCL_EXT_XYZ_POINT_TYPES
#define PCL_EXT_XYZ_POINT_TYPES                                                        \
  (pcl::PointXYZ) (pcl::PointXYZI) (pcl::PointXYZL) (pcl::PointXYZRGB) (               \
      pcl::PointXYZRGBA) (pcl::PointXYZRGBL) (pcl::PointNormal) (                      \
      pcl::PointXYZINormal) (pcl::PointXYZRGBNormal)
#endif

/** \brief PCL_EXT_INSTANTIATE(Name, TYPES) expands PCL_EXT_INSTANTIATE_Name(T) for each
 * type, as PCL_INSTANTIATE does for PCL's own classes; nothing under PCL_NO_PRECOMPILE.
 */
#ifdef PCL_NO_PRECOMPILE
#define PCL_EXT_INSTANTIATE(TEMPLATE, POINT_TYPES)
#else
#define PCL_EXT_INSTANTIATE_IMPL(r, TEMPLATE, POINT_TYPE)                              \
  BOOST_PP_CAT (PCL_EXT_INSTANTIATE_, TEMPLATE) (POINT_TYPE)
#define PCL_EXT_INSTANTIATE(TEMPLATE, POINT_TYPES)                                     \
  BOOST_PP_SEQ_FOR_EACH (PCL_EXT_INSTANTIATE_IMPL, TEMPLATE, POINT_TYPES)
#endif
