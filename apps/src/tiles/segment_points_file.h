/*
 * pcl_ext_tiles: the points of a tiled run grouped by segment in two work files, read
 * one segment at a time.
 */
#pragma once

#include <pcl_ext/segmentation/cylinder_join.h>

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The segmented points of a tiled run, segment after segment, each segment's
 * points by ascending global index (the order in which CylinderSegmentJoin lists the
 * whole cloud's), in two files of the work folder: `<name>.xyz` (three FLOAT32 a point,
 * relative to the plan's origin) and `<name>.index` (the UINT64 global index). A
 * cylinder_join::SegmentSource that loads one segment at a time, centred on the mean of
 * all the points (summed in that order, as CylinderSegmentJoin sums them), so that the
 * join need not hold the cloud: 20 bytes a point on disk, 8 bytes a segment in memory.
 * The files are removed with the object. */
class SegmentPointsFile : public cylinder_join::SegmentSource {
public:
  SegmentPointsFile() = default;
  SegmentPointsFile (const SegmentPointsFile&) = delete;
  SegmentPointsFile&
  operator= (const SegmentPointsFile&) = delete;
  ~SegmentPointsFile() override;

  /** \brief Group the points: \a segments segments, each point's segment in \a
   * workdir's results (tiling::TileResults; kNoResult: in none), its coordinates in the
   * point files \a point_files (readProfilePart; together every finite point once) of
   * the \a total points. Holds 4 bytes a point while it sorts them into the files.
   * \return false (message printed) when a file cannot be read or written or a result
   * names no segment */
  bool
  build (const std::string& workdir,
         const std::vector<std::string>& point_files,
         std::uint32_t segments,
         std::uint64_t total);

  std::size_t
  size () const override
  {
    return first_.empty() ? 0 : first_.size() - 1;
  }

  std::size_t
  pointCount (std::size_t s) const override
  {
    return static_cast<std::size_t> (first_[s + 1] - first_[s]);
  }

  /** \brief Segment \a s's coordinates, relative to getCentre(). */
  bool
  load (std::size_t s, std::vector<Eigen::Vector3d>& points) const override;

  /** \brief Segment \a s's global indices, ascending. \return false (message printed)
   * when the file cannot be read */
  bool
  loadIndices (std::size_t s, std::vector<std::uint64_t>& indices) const;

  /** \brief The mean of all the points, relative to the plan's origin. */
  const Eigen::Vector3d&
  getCentre () const
  {
    return centre_;
  }

private:
  bool
  open (const std::string& workdir);
  bool
  sortSegments ();
  void
  close ();

  std::vector<std::uint64_t> first_; ///< each segment's first point; the total last
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();
  std::string xyz_path_, index_path_;
  int xyz_ = -1, index_ = -1;
};
} // namespace apps
} // namespace pcl_ext
