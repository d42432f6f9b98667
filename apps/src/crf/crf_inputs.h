/*
 * pcl_ext: reading labelled clouds for the CRF apps (PCD / PLY with a label field, or
 * Oakland).
 */
#pragma once

#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/io/class_mapping.h>

#include <pcl/PCLPointCloud2.h>

#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief A cloud read for the CRF: its blob (for writing the result back), the CRF
 * input and, when the file has them, the labels (mapped through the class file when
 * given). */
struct CrfCloud {
  pcl::PCLPointCloud2 blob;
  CrfInput input;
  std::vector<std::uint32_t> labels; ///< empty when the file has no labels
};

/** \brief Read a PCD/PLY (x y z, optional rgb/rgba, intensity, label) or an Oakland
 * file
 * (.xyz_label_conf; labels mapped with \a mapping, which is then required).
 * \return false with \a error set on failure */
bool
loadCrfCloud (const std::string& path,
              const io::ClassMapping* mapping,
              CrfCloud& cloud,
              std::string& error);
} // namespace apps
} // namespace pcl_ext
