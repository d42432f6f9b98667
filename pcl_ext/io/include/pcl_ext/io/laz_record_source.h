/*
 * pcl_ext: the point records of a LAZ file, decompressed chunk by chunk.
 */
#pragma once

#include <pcl_ext/io/las_record_source.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
/** Open the compressed point data of a LAZ file. \param path the file; \param
 * point_data_offset the header's offset to point data; \param point_format the LAS
 * point format (0-10, compression bits cleared); \param record_length the point record
 * length; \param point_count the number of points; \param laszip_vlr the payload of the
 * LASzip VLR (user id "laszip encoded", record id 22204). \throw ReadError naming the
 * file on a malformed VLR, chunk table or data */
std::unique_ptr<LasRecordSource>
makeLazRecordSource (const std::string& path,
                     std::uint64_t point_data_offset,
                     int point_format,
                     std::size_t record_length,
                     std::uint64_t point_count,
                     const std::vector<std::uint8_t>& laszip_vlr);
} // namespace io
} // namespace pcl_ext
