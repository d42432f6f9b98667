/*
 * pcl_ext: any point file read in chunks, with coordinates relative to a chosen origin.
 */
#include <pcl_ext/tiling/point_file_chunks.h>

#include <pcl_ext/io/read_error.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace pcl_ext {
namespace tiling {
PointFileChunks::PointFileChunks() = default;

PointFileChunks::~PointFileChunks() = default;

void
PointFileChunks::open (const std::string& path)
{
  las_.reset();
  whole_ = pcl::PCLPointCloud2();
  description_ = io::PointFile();
  next_ = 0;
  path_ = path;
  const io::PointFileFormat format = io::detectPointFileFormat (path);
  if (format == io::PointFileFormat::LAS || format == io::PointFileFormat::LAZ) {
    auto reader = std::make_unique<io::LasReader>();
    reader->open (path);
    description_.format = format;
    description_.las = reader->getFileInfo();
    file_origin_ = reader->getOrigin();
    count_ = reader->getPointCount();
    min_ = reader->getHeader().min;
    max_ = reader->getHeader().max;
    las_ = std::move (reader);
  }
  else {
    io::loadPointFile (path, description_);
    whole_ = std::move (description_.cloud);
    description_.cloud = pcl::PCLPointCloud2();
    description_.cloud.fields = whole_.fields;
    description_.cloud.point_step = whole_.point_step;
    file_origin_ = description_.origin;
    count_ = static_cast<std::uint64_t> (whole_.width) * whole_.height;
    min_.setConstant (std::numeric_limits<double>::infinity());
    max_.setConstant (-std::numeric_limits<double>::infinity());
    const std::size_t at = xyzOffset (whole_);
    float xyz[3];
    for (std::uint64_t i = 0; i < count_; ++i) {
      std::memcpy (xyz, whole_.data.data() + i * whole_.point_step + at, sizeof (xyz));
      if (!std::isfinite (xyz[0]) || !std::isfinite (xyz[1]) || !std::isfinite (xyz[2]))
        continue;
      for (int a = 0; a < 3; ++a) {
        min_[a] = std::min (min_[a], file_origin_[a] + xyz[a]);
        max_[a] = std::max (max_[a], file_origin_[a] + xyz[a]);
      }
    }
  }
  origin_ = file_origin_;
}

void
PointFileChunks::setOrigin (const Eigen::Vector3d& origin)
{
  if (!origin.allFinite())
    return;
  origin_ = origin;
  if (las_)
    las_->setOrigin (origin);
}

std::size_t
PointFileChunks::read (std::size_t max_points, pcl::PCLPointCloud2& chunk)
{
  if (las_)
    return las_->read (max_points, chunk);
  const std::size_t n =
      static_cast<std::size_t> (std::min<std::uint64_t> (max_points, count_ - next_));
  chunk.fields = whole_.fields;
  chunk.point_step = whole_.point_step;
  chunk.is_bigendian = whole_.is_bigendian;
  chunk.height = 1;
  chunk.width = static_cast<std::uint32_t> (n);
  chunk.row_step = chunk.point_step * chunk.width;
  chunk.is_dense = false;
  const auto* first = whole_.data.data() + next_ * whole_.point_step;
  chunk.data.assign (first, first + n * whole_.point_step);
  if (origin_ != file_origin_) {
    const Eigen::Vector3d shift = file_origin_ - origin_;
    const std::size_t at = xyzOffset (chunk);
    for (std::size_t i = 0; i < n; ++i) {
      float xyz[3];
      std::uint8_t* p = chunk.data.data() + i * chunk.point_step + at;
      std::memcpy (xyz, p, sizeof (xyz));
      for (int a = 0; a < 3; ++a)
        xyz[a] = static_cast<float> (static_cast<double> (xyz[a]) + shift[a]);
      std::memcpy (p, xyz, sizeof (xyz));
    }
  }
  next_ += n;
  return n;
}

void
PointFileChunks::rewind()
{
  if (las_) {
    const Eigen::Vector3d origin = origin_;
    open (path_);
    setOrigin (origin);
  }
  else
    next_ = 0;
}

std::size_t
xyzOffset (const pcl::PCLPointCloud2& chunk)
{
  for (std::size_t f = 0; f + 2 < chunk.fields.size(); ++f)
    if (chunk.fields[f].name == "x" && chunk.fields[f + 1].name == "y" &&
        chunk.fields[f + 2].name == "z" &&
        chunk.fields[f].datatype == pcl::PCLPointField::FLOAT32 &&
        chunk.fields[f + 1].offset == chunk.fields[f].offset + 4 &&
        chunk.fields[f + 2].offset == chunk.fields[f].offset + 8)
      return chunk.fields[f].offset;
  throw std::invalid_argument ("the points have no consecutive FLOAT32 x y z");
}
} // namespace tiling
} // namespace pcl_ext
