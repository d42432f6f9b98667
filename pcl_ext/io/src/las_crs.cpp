/*
 * pcl_ext: the coordinate reference system a LAS file declares, to compare files.
 */
#include <pcl_ext/io/las_crs.h>

#include <cctype>
#include <cstdint>
#include <cstring>

namespace pcl_ext {
namespace io {
namespace {
constexpr const char* kProjectionUser = "LASF_Projection";
constexpr std::uint16_t kWktRecord = 2112;
constexpr std::uint16_t kGeoKeyDirectory = 34735;
constexpr std::uint16_t kGeoDoubleParams = 34736;
constexpr std::uint16_t kGeoAsciiParams = 34737;
constexpr std::uint16_t kProjectedCsTypeKey = 3072;
constexpr std::uint16_t kGeographicTypeKey = 2048;
constexpr std::uint16_t kUserDefined = 32767;

const LasVariableLengthRecord*
findRecord (const LasFileInfo& info, std::uint16_t record_id)
{
  for (const auto* records : {&info.vlrs, &info.evlrs})
    for (const auto& r : *records)
      if (r.user_id == kProjectionUser && r.record_id == record_id)
        return &r;
  return nullptr;
}

/** The WKT without its trailing NULs and the white space outside quoted names. */
std::string
compactWkt (const std::vector<std::uint8_t>& data)
{
  std::string wkt;
  bool quoted = false;
  for (const std::uint8_t c : data) {
    if (c == 0)
      break;
    quoted = quoted != (c == '"');
    if (quoted || !std::isspace (c))
      wkt.push_back (static_cast<char> (c));
  }
  return wkt;
}

/** The EPSG code of the authority of the outermost CRS of \a wkt (compacted): the last
 * AUTHORITY[...] or ID[...] directly inside its brackets; empty when there is none. */
std::string
outermostEpsgCode (const std::string& wkt)
{
  std::string code;
  int depth = 0;
  bool quoted = false;
  for (std::size_t i = 0; i < wkt.size(); ++i) {
    const char c = wkt[i];
    if (c == '"') {
      quoted = !quoted;
      continue;
    }
    if (quoted)
      continue;
    if (c == '[' || c == '(')
      ++depth;
    else if (c == ']' || c == ')')
      --depth;
    else if (depth == 1 && (i == 0 || wkt[i - 1] == ',')) {
      for (const char* keyword : {"AUTHORITY[", "ID["}) {
        const std::size_t length = std::strlen (keyword);
        if (wkt.compare (i, length, keyword) != 0)
          continue;
        // "EPSG", then the code, quoted (WKT 1) or not (WKT 2).
        std::size_t at = i + length;
        if (wkt.compare (at, 7, "\"EPSG\",") != 0)
          break;
        at += 7;
        if (at < wkt.size() && wkt[at] == '"')
          ++at;
        std::string digits;
        while (at < wkt.size() && std::isdigit (static_cast<unsigned char> (wkt[at])))
          digits.push_back (wkt[at++]);
        if (!digits.empty())
          code = digits;
        break;
      }
    }
  }
  return code;
}

/** The name of the outermost CRS of \a wkt (compacted): its first quoted string. */
std::string
outermostName (const std::string& wkt)
{
  const std::size_t open = wkt.find ('"');
  const std::size_t close = open == std::string::npos ? open : wkt.find ('"', open + 1);
  return close == std::string::npos ? wkt : wkt.substr (open + 1, close - open - 1);
}

/** The value of GeoTIFF key \a key held in the directory itself, or 0. */
std::uint16_t
geoKeyValue (const std::vector<std::uint8_t>& directory, std::uint16_t key)
{
  const auto word = [&directory] (std::size_t i) {
    std::uint16_t w;
    std::memcpy (&w, directory.data() + 2 * i, 2); // little-endian, as the file
    return w;
  };
  const std::size_t words = directory.size() / 2;
  if (words < 4)
    return 0;
  const std::size_t keys = word (3);
  for (std::size_t k = 0; k < keys && 4 * (k + 2) <= words; ++k) {
    const std::size_t e = 4 * (k + 1);
    if (word (e) == key && word (e + 1) == 0 && word (e + 2) == 1)
      return word (e + 3);
  }
  return 0;
}
} // namespace

std::string
LasCoordinateSystem::describe() const
{
  switch (kind) {
  case Kind::Epsg:
    return "EPSG:" + value;
  case Kind::Wkt:
    return "the CRS named \"" + value + "\"";
  case Kind::GeoTiff:
    return "a user-defined GeoTIFF CRS";
  case Kind::Text:
    return "the CRS described as \"" + value + "\"";
  case Kind::None:
    break;
  }
  return "no CRS";
}

CrsMatch
matchCoordinateSystems (const LasCoordinateSystem& a, const LasCoordinateSystem& b)
{
  using Kind = LasCoordinateSystem::Kind;
  if (!a.declared() || !b.declared() || a.kind != b.kind)
    return CrsMatch::Unknown;
  if (a.value == b.value)
    return CrsMatch::Same;
  return a.kind == Kind::GeoTiff || a.kind == Kind::Text ? CrsMatch::Unknown
                                                         : CrsMatch::Different;
}

LasCoordinateSystem
textCoordinateSystem (const std::string& text)
{
  LasCoordinateSystem crs;
  const std::string compact =
      compactWkt (std::vector<std::uint8_t> (text.begin(), text.end()));
  if (compact.empty())
    return crs;
  std::string upper;
  for (const char c : compact)
    upper.push_back (static_cast<char> (std::toupper (static_cast<unsigned char> (c))));
  for (const char* prefix : {"EPSG:", "URN:OGC:DEF:CRS:EPSG::"}) {
    const std::size_t length = std::strlen (prefix);
    if (upper.compare (0, length, prefix) == 0 && upper.size() > length &&
        upper.find_first_not_of ("0123456789", length) == std::string::npos) {
      crs.kind = LasCoordinateSystem::Kind::Epsg;
      crs.value = compact.substr (length);
      return crs;
    }
  }
  // WKT: a keyword, then the CRS's bracket.
  const std::size_t bracket = compact.find_first_of ("[(");
  const bool wkt =
      bracket != std::string::npos && bracket > 0 &&
      compact.find_first_not_of ("ABCDEFGHIJKLMNOPQRSTUVWXYZ_", 0) == bracket;
  if (wkt) {
    const std::string code = outermostEpsgCode (compact);
    crs.kind =
        code.empty() ? LasCoordinateSystem::Kind::Wkt : LasCoordinateSystem::Kind::Epsg;
    crs.value = code.empty() ? outermostName (compact) : code;
    return crs;
  }
  crs.kind = LasCoordinateSystem::Kind::Text;
  crs.value = text;
  return crs;
}

LasCoordinateSystem
lasCoordinateSystem (const LasFileInfo& info)
{
  LasCoordinateSystem crs;
  if (const auto* wkt = findRecord (info, kWktRecord)) {
    const std::string text = compactWkt (wkt->data);
    if (!text.empty()) {
      const std::string code = outermostEpsgCode (text);
      crs.kind = code.empty() ? LasCoordinateSystem::Kind::Wkt
                              : LasCoordinateSystem::Kind::Epsg;
      crs.value = code.empty() ? outermostName (text) : code;
      return crs;
    }
  }
  const auto* directory = findRecord (info, kGeoKeyDirectory);
  if (!directory || directory->data.size() < 8)
    return LasCoordinateSystem();
  for (const std::uint16_t key : {kProjectedCsTypeKey, kGeographicTypeKey}) {
    const std::uint16_t code = geoKeyValue (directory->data, key);
    if (code != 0 && code != kUserDefined) {
      crs.kind = LasCoordinateSystem::Kind::Epsg;
      crs.value = std::to_string (code);
      return crs;
    }
  }
  crs.kind = LasCoordinateSystem::Kind::GeoTiff;
  for (const std::uint16_t id : {kGeoKeyDirectory, kGeoDoubleParams, kGeoAsciiParams})
    if (const auto* r = findRecord (info, id))
      crs.value.append (r->data.begin(), r->data.end()).push_back ('|');
  return crs;
}
} // namespace io
} // namespace pcl_ext
