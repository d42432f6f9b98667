/*
 * pcl_ext: LAZ files in a build without the LASzip decompressor.
 */
#include <pcl_ext/io/laz_record_source.h>
#include <pcl_ext/io/read_error.h>

namespace pcl_ext {
namespace io {
std::unique_ptr<LasRecordSource>
makeLazRecordSource (const std::string& path,
                     std::uint64_t,
                     int,
                     std::size_t,
                     std::uint64_t,
                     const std::vector<std::uint8_t>&)
{
  throw ReadError (path, 0, "LAZ decompression is not available in this build");
}
} // namespace io
} // namespace pcl_ext
