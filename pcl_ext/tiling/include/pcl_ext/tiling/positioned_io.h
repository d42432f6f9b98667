/*
 * pcl_ext: whole reads and writes at an offset of an open file (pread / pwrite), for
 * work files that several threads or processes use at once.
 */
#pragma once

#include <cstddef>
#include <cstdint>

namespace pcl_ext {
namespace tiling {
/** \brief Write all \a size bytes of \a bytes at \a offset of the file \a fd, again
 * where a call writes less or is interrupted. \return false when the disk is full or
 * the write fails (errno tells why) */
bool
writeAllAt (int fd, const void* bytes, std::size_t size, std::uint64_t offset);

/** \brief Read all \a size bytes at \a offset of the file \a fd into \a bytes.
 * \return false when the file ends first or the read fails */
bool
readAllAt (int fd, void* bytes, std::size_t size, std::uint64_t offset);
} // namespace tiling
} // namespace pcl_ext
