/*
 * pcl_ext: LAS variable length records and extra-bytes descriptors (ASPRS LAS 1.4 R15,
 * sections 2.5-2.7 and 2.6.3).
 */
#include <pcl_ext/io/las_header.h>
#include <pcl_ext/io/read_error.h>

#include "las_bytes.h"

namespace pcl_ext {
namespace io {
namespace {
constexpr std::size_t kDescriptorSize = 192;
} // namespace

int
LasExtraBytesDescriptor::elements() const
{
  return data_type <= 10 ? 1 : data_type <= 20 ? 2 : 3;
}

int
LasExtraBytesDescriptor::baseType() const
{
  return data_type <= 10 ? data_type : (data_type - 1) % 10 + 1;
}

std::size_t
LasExtraBytesDescriptor::elementSize() const
{
  static const std::size_t sizes[] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
  return data_type == 0 ? options : sizes[baseType()];
}

bool
isExtraBytesRecord (const LasVariableLengthRecord& vlr)
{
  return vlr.user_id == "LASF_Spec" && vlr.record_id == 4;
}

bool
isLaszipRecord (const LasVariableLengthRecord& vlr)
{
  return vlr.user_id == "laszip encoded" && vlr.record_id == 22204;
}

std::vector<LasExtraBytesDescriptor>
parseExtraBytes (const LasVariableLengthRecord& vlr, const std::string& path)
{
  if (vlr.data.size() % kDescriptorSize != 0)
    throw ReadError (path,
                     0,
                     "the extra-bytes record holds " +
                         std::to_string (vlr.data.size()) +
                         " bytes, not a multiple of 192");
  std::vector<LasExtraBytesDescriptor> out (vlr.data.size() / kDescriptorSize);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::uint8_t* p = vlr.data.data() + i * kDescriptorSize;
    auto& d = out[i];
    std::copy_n (p, 2, d.reserved.begin());
    d.data_type = p[2];
    d.options = p[3];
    d.name = las::getString (p + 4, 32);
    std::copy_n (p + 36, 4, d.unused.begin());
    for (int e = 0; e < 3; ++e) {
      std::copy_n (p + 40 + 8 * e, 8, d.no_data[e].begin());
      std::copy_n (p + 64 + 8 * e, 8, d.min[e].begin());
      std::copy_n (p + 88 + 8 * e, 8, d.max[e].begin());
      d.scale[e] = las::get<double> (p + 112 + 8 * e);
      d.offset[e] = las::get<double> (p + 136 + 8 * e);
    }
    d.description = las::getString (p + 160, 32);
    if (d.data_type > 30 || (d.data_type == 0 && d.options == 0))
      throw ReadError (path,
                       0,
                       "extra-bytes descriptor " + std::to_string (i) + " (\"" +
                           d.name + "\") has an invalid data type " +
                           std::to_string (d.data_type) +
                           (d.data_type == 0 ? " with no length" : ""));
  }
  return out;
}

std::vector<std::uint8_t>
encodeExtraBytes (const std::vector<LasExtraBytesDescriptor>& descriptors)
{
  std::vector<std::uint8_t> out (descriptors.size() * kDescriptorSize);
  for (std::size_t i = 0; i < descriptors.size(); ++i) {
    std::uint8_t* p = out.data() + i * kDescriptorSize;
    const auto& d = descriptors[i];
    std::copy (d.reserved.begin(), d.reserved.end(), p);
    p[2] = d.data_type;
    p[3] = d.options;
    las::putString (p + 4, 32, d.name);
    std::copy (d.unused.begin(), d.unused.end(), p + 36);
    for (int e = 0; e < 3; ++e) {
      std::copy (d.no_data[e].begin(), d.no_data[e].end(), p + 40 + 8 * e);
      std::copy (d.min[e].begin(), d.min[e].end(), p + 64 + 8 * e);
      std::copy (d.max[e].begin(), d.max[e].end(), p + 88 + 8 * e);
      las::put (p + 112 + 8 * e, d.scale[e]);
      las::put (p + 136 + 8 * e, d.offset[e]);
    }
    las::putString (p + 160, 32, d.description);
  }
  return out;
}
} // namespace io
} // namespace pcl_ext
