/*
 * pcl_ext: the points of a pcl::PCLPointCloud2 as LAS point records (ASPRS LAS 1.4 R15,
 * sections 2.6.1-2.6.11 and the extra bytes of 2.6.3).
 */
#pragma once

#include <pcl_ext/io/las_header.h>

#include "las_point_layout.h"

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace las {
/** A field of the cloud: where it is and its type (absent: type 0). */
struct CloudField {
  std::size_t offset = 0;
  Type type = 0;
  std::size_t count = 0;
};

/** Encodes the points of one cloud as records of one point format (see saveLas for the
 * rules). */
class RecordEncoder {
public:
  /** Maps the fields of \a cloud to the records of \a format. \a like (may be null)
   * gives the extra-bytes descriptors to keep and whether las_x/y/z may be used.
   * \return false, with \a error set, when a field cannot be stored */
  bool
  init (const pcl::PCLPointCloud2& cloud,
        int format,
        const Eigen::Vector3d& scale,
        const Eigen::Vector3d& offset,
        const Eigen::Vector3d& origin,
        const LasFileInfo* like,
        std::string& error);

  std::size_t
  recordLength () const
  {
    return record_length_;
  }

  /** The extra-bytes descriptors of the records. */
  const std::vector<LasExtraBytesDescriptor>&
  descriptors () const
  {
    return descriptors_;
  }

  /** Whether the descriptors are exactly those of \a like (its VLR can be kept). */
  bool
  keepsLikeDescriptors () const
  {
    return keeps_like_;
  }

  /** Encodes the point at \a point into \a record (zeroed first); \a xyz receives its
   * integers. \return false, with \a error set, when a coordinate is not finite or does
   * not fit an int32 */
  bool
  encode (const std::uint8_t* point,
          std::uint8_t* record,
          std::array<std::int32_t, 3>& xyz,
          std::string& error) const;

private:
  struct Step {
    CloudField from;
    std::size_t to = 0; ///< byte in the record
    Type storage = 0;
    int shift = 0, bits = 0;
    double fallback = 0.0; ///< the value of an absent field
    bool scaled = false;
    double scale = 1.0, offset = 0.0;
  };

  std::vector<Step> steps_;
  std::array<CloudField, 3> coordinates_, integers_;
  CloudField red_, green_, blue_, rgb_;
  std::size_t red_at_ = 0;
  std::array<bool, 3> use_integers_{};
  bool colour_ = false, keeps_like_ = false;
  Eigen::Vector3d scale_, shift_, origin_minus_offset_;
  std::size_t record_length_ = 0;
  std::vector<LasExtraBytesDescriptor> descriptors_;
};
} // namespace las
} // namespace io
} // namespace pcl_ext
