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
 * file on a malformed VLR, chunk table or data
 *
 * Implements the LASzip compressed format (pointwise chunked POINT10, GPSTIME11, RGB12,
 * BYTE v2 items for point formats 0-3; layered chunked POINT14, RGB14, RGBNIR14, BYTE14
 * v3 and v4 items for point formats 6-8, as in COPC); see parseLaszipVlr for what is
 * refused (wave packets, v1 items, compressors 0 and 1) and docs/laz.md. The point data
 * starts with the offset of the chunk table; the table gives each chunk's bytes, and
 * with variable chunks (chunk size 0xFFFFFFFF, COPC) each chunk's points. Without a
 * table (its offset still points at itself) fixed-size chunks are decoded one after the
 * other. The records are decoded one chunk at a time: memory is one chunk's compressed
 * bytes. The VLR, the table offset and the chunk table are checked here, each chunk
 * when it is reached (readRecords throws ReadError naming the file and the chunk). */
std::unique_ptr<LasRecordSource>
makeLazRecordSource (const std::string& path,
                     std::uint64_t point_data_offset,
                     int point_format,
                     std::size_t record_length,
                     std::uint64_t point_count,
                     const std::vector<std::uint8_t>& laszip_vlr);
} // namespace io
} // namespace pcl_ext
