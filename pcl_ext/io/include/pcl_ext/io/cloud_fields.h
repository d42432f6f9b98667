/*
 * pcl_ext: reading and writing one named field of a pcl::PCLPointCloud2, whatever its
 * type.
 */
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** \brief Read field \a name of every point as a label.
 *
 * Works for any PCL field type (int8 ... uint32, float32, float64; the first element
 * when the field has a count above 1), so ground truth stored as `label` (uint32),
 * `segment` (int32) or `class` (float) all read the same. The rule: NaN and negative
 * values (e.g. -1 for "none") become 0; float values must be whole numbers and at most
 * 2^32 - 1. \param[in] cloud the cloud \param[in] name the field name \param[out]
 * labels one label per point (width x height), unchanged on failure \param[out] error
 * when not null, receives the reason of a failure \return false when the field does not
 * exist, a value is not a whole number or too large, or the cloud's data is shorter
 * than its size claims
 */
bool
getLabelField (const pcl::PCLPointCloud2& cloud,
               const std::string& name,
               std::vector<std::uint32_t>& labels,
               std::string* error = nullptr);

/** \brief Write \a labels into a uint32 field \a name, overwriting it in place when it
 * already is a single uint32, otherwise replacing it (or, when absent, appending it)
 * and repacking the points. \return false when labels.size () differs from the number
 * of points
 */
bool
setLabelField (pcl::PCLPointCloud2& cloud,
               const std::string& name,
               const std::vector<std::uint32_t>& labels);

/** \brief Write \a values into a float32 field \a name (a score or a probability per
 * point), as setLabelField writes labels: in place when the field already is a single
 * float32, otherwise replacing or appending it. \return false when values.size ()
 * differs from the number of points
 */
bool
setFloatField (pcl::PCLPointCloud2& cloud,
               const std::string& name,
               const std::vector<float>& values);
/** \brief The fields of clouds of different layouts in one layout (e.g. the scans of a
 * project written into one file): those of \a layouts[0] in their order, then each
 * field of the next layouts not seen yet, packed; no points. Fields of one name must
 * have one type and count.
 * \param[out] error the fields of one name and two types, when that fails
 * \return false when two layouts give a name two types or counts */
bool
unionOfFields (const std::vector<pcl::PCLPointCloud2>& layouts,
               pcl::PCLPointCloud2& result,
               std::string& error);

/** \brief \a cloud's points in the layout \a fields (e.g. unionOfFields): each field of
 * \a fields copied from \a cloud's field of that name, 0 where \a cloud has none,
 * except colour, which is kept whether a cloud holds it packed (`rgb`, `rgba`: 8 bits a
 * channel) or as `red green blue` (8 bits, or 16 bits as 8 bits x 257). Width, height,
 * header and is_dense are kept. */
void
conformToFields (const pcl::PCLPointCloud2& cloud,
                 const pcl::PCLPointCloud2& fields,
                 pcl::PCLPointCloud2& result);
} // namespace io
} // namespace pcl_ext
