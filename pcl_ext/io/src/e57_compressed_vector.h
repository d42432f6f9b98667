/*
 * pcl_ext: the records of an E57 compressed vector (private header).
 */
#pragma once

#include "e57_paged_file.h"

#include <functional>
#include <string>
#include <vector>

namespace pcl_ext {
namespace io {
namespace detail {
/** Receives decoded records: \a count records of prototype.size () values each, record
 * after record (values of Integer and ScaledInteger fields already scaled). */
using E57RecordSink =
    std::function<void (const std::vector<double>& values, std::size_t count)>;

/** Decodes the records of \a scan's points (ASTM E2807 sections 9.7 to 9.9): the
 * compressed-vector section header at scan.file_offset, its data packets (index and
 * empty packets are skipped) and their bit-packed bytestreams, one per prototype field.
 * Throws ReadError (naming \a where) when the section header is not one of a compressed
 * vector or lies outside the file, when a packet's length points outside the section or
 * its bytestreams do not fit in it, when a packet has another number of bytestreams
 * than the prototype has fields, when an integer lies outside its declared range, or
 * when the section holds fewer records than scan.record_count. */
void
decodeE57Points (E57PagedFile& file,
                 const E57ScanInfo& scan,
                 const std::string& where,
                 const E57RecordSink& sink);
} // namespace detail
} // namespace io
} // namespace pcl_ext
