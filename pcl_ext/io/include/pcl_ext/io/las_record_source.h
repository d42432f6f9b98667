/*
 * pcl_ext: the source of raw LAS point records (a LAS file or a LAZ decoder).
 */
#pragma once
#include <cstddef>
#include <cstdint>
namespace pcl_ext {
namespace io {
/** \brief A stream of raw LAS point records, exactly as an uncompressed LAS file stores
 * them (ASPRS LAS 1.4 R15, section 2.6-2.16): decoded from LAZ or read from the file.
 */
class LasRecordSource {
public:
  virtual ~LasRecordSource() = default;
  /** \brief Decode the next \a n records (record length bytes each) into \a out;
   * returns how many were decoded (fewer only at the end). \throw ReadError on corrupt
   * data */
  virtual std::size_t
  readRecords (std::size_t n, std::uint8_t* out) = 0;
};
} // namespace io
} // namespace pcl_ext
