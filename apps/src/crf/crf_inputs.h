/*
 * pcl_ext: reading labelled clouds for the CRF apps (any point file, labels in a
 * `label` field, or Oakland).
 */
#pragma once

#include <pcl_ext/apps/output.h>
#include <pcl_ext/classification/crf_model.h>
#include <pcl_ext/io/class_mapping.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/PCLPointCloud2.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief A cloud read for the CRF: the file (for writing the result back in its
 * frame), the CRF input and, when the file has them, the labels (mapped through the
 * class file when given). */
struct CrfCloud {
  io::PointFile file;
  CrfInput input;
  std::vector<std::uint32_t> labels; ///< empty when the file has no labels
};

/** \brief The field the CRF's classes are written to (`crf_class`, -output_field), and
 * -asprs (ASPRS codes in a LAS output's Classification, by class name). */
ResultField
crfClassField ();

/** \brief The CRF's colour (rgb / rgba normalised to r, g, b over their sum; a third
 * each for black) and intensity (0 where not finite) of the points of \a blob, into
 * whichever of \a colours and \a intensity is given; each left empty when \a blob
 * has no such field. */
void
readCrfAttributes (const pcl::PCLPointCloud2& blob,
                   std::vector<Eigen::Vector3f>* colours,
                   std::vector<float>* intensity);

/** \brief The ASPRS code of each class id of a model (by its name, asprsClass; 1,
 * unclassified, for the classes without a code), each printed on stdout with the
 * classes left at 1. */
std::map<std::uint32_t, std::uint32_t>
crfAsprsCodes (const std::map<std::uint32_t, std::string>& names);

/** \brief Read a point file of any format io::loadPointFile reads (x y z, optional
 * rgb/rgba, intensity, label) or an Oakland file (.xyz_label_conf; labels mapped with
 * \a mapping, which is then required).
 * \return false with \a error set on failure */
bool
loadCrfCloud (const std::string& path,
              const io::ClassMapping* mapping,
              CrfCloud& cloud,
              std::string& error);
} // namespace apps
} // namespace pcl_ext
