/*
 * pcl_ext: the scan descriptions of an E57 file's XML section, parsed with libexpat.
 */
#include <pcl_ext/io/e57_format.h>

#include "text_lines.h"

#include <expat.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <memory>

namespace pcl_ext {
namespace io {
namespace {
constexpr int kMaxDepth = 64;

/** An element of the XML section: what the E57 layer needs of a DOM. */
struct XmlNode {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::string text;
  std::vector<std::unique_ptr<XmlNode>> children;

  const XmlNode*
  child (const std::string& n) const
  {
    for (const auto& c : children)
      if (c->name == n)
        return c.get();
    return nullptr;
  }

  const std::string*
  attribute (const std::string& n) const
  {
    for (const auto& a : attributes)
      if (a.first == n)
        return &a.second;
    return nullptr;
  }
};

struct Builder {
  XmlNode root; // holds the document element as its only child
  std::vector<XmlNode*> stack{&root};
  std::string error;
  XML_Parser parser = nullptr;
};

void XMLCALL
onStart (void* data, const XML_Char* name, const XML_Char** attributes)
{
  auto* b = static_cast<Builder*> (data);
  if (static_cast<int> (b->stack.size()) > kMaxDepth) {
    b->error =
        "the XML is nested deeper than " + std::to_string (kMaxDepth) + " levels";
    XML_StopParser (b->parser, XML_FALSE);
    return;
  }
  auto node = std::make_unique<XmlNode>();
  node->name = name;
  for (int i = 0; attributes[i]; i += 2)
    node->attributes.emplace_back (attributes[i], attributes[i + 1]);
  XmlNode* raw = node.get();
  b->stack.back()->children.push_back (std::move (node));
  b->stack.push_back (raw);
}

void XMLCALL
onEnd (void* data, const XML_Char*)
{
  auto* b = static_cast<Builder*> (data);
  if (b->stack.size() > 1)
    b->stack.pop_back();
}

void XMLCALL
onText (void* data, const XML_Char* text, int size)
{
  auto* b = static_cast<Builder*> (data);
  b->stack.back()->text.append (text, static_cast<std::size_t> (size));
}

class Parser {
public:
  Parser (const std::string& path) : path_ (path) {}

  [[noreturn]] void
  fail (const std::string& message) const
  {
    throw ReadError (path_, 0, "XML section: " + message);
  }

  bool
  integer (const std::string& text, std::int64_t& value) const
  {
    const std::string_view t = detail::trim (text);
    if (t.empty())
      return false;
    const char* begin = t.data() + (t.front() == '+' ? 1 : 0);
    const auto r = std::from_chars (begin, t.data() + t.size(), value);
    return r.ec == std::errc() && r.ptr == t.data() + t.size();
  }

  bool
  real (const std::string& text, double& value) const
  {
    return detail::parseDouble (detail::trim (text), value);
  }

  /** Numeric value of an element of type Integer, ScaledInteger or Float; \a fallback
   * when the element is absent, 0 when it is empty (the standard's default). */
  double
  number (const XmlNode* parent, const std::string& name, double fallback) const
  {
    const XmlNode* n = parent ? parent->child (name) : nullptr;
    if (!n)
      return fallback;
    if (detail::trim (n->text).empty())
      return 0.0;
    double v = 0.0;
    const std::string* type = n->attribute ("type");
    if (!real (n->text, v) || !std::isfinite (v))
      fail (name + ": " + detail::quote (n->text) + " is not a finite number");
    if (type && *type == "ScaledInteger") {
      double scale = 1.0, offset = 0.0;
      if (const std::string* s = n->attribute ("scale"))
        if (!real (*s, scale))
          fail (name + ": bad scale");
      if (const std::string* o = n->attribute ("offset"))
        if (!real (*o, offset))
          fail (name + ": bad offset");
      v = v * scale + offset;
    }
    return v;
  }

  std::string
  text (const XmlNode& parent, const std::string& name) const
  {
    const XmlNode* n = parent.child (name);
    return n ? std::string (detail::trim (n->text)) : std::string();
  }

  void
  flatten (const XmlNode& node, int depth, std::vector<E57Field>& fields) const
  {
    if (depth > kMaxDepth)
      fail ("the prototype is nested too deeply");
    for (const auto& c : node.children) {
      const std::string* type = c->attribute ("type");
      const std::string kind = type ? *type : "";
      if (kind == "Structure" || kind == "Vector") {
        flatten (*c, depth + 1, fields);
        continue;
      }
      fields.push_back (field (*c, kind));
    }
  }

  E57Field
  field (const XmlNode& n, const std::string& kind) const
  {
    E57Field f;
    f.name = n.name;
    const std::string where = "prototype element " + n.name;
    const std::string* min = n.attribute ("minimum");
    const std::string* max = n.attribute ("maximum");
    if (kind == "Integer" || kind == "ScaledInteger") {
      f.type = kind == "Integer" ? E57FieldType::Integer : E57FieldType::ScaledInteger;
      if ((min && !integer (*min, f.minimum)) || (max && !integer (*max, f.maximum)))
        fail (where + ": minimum or maximum is not a 64-bit integer");
      if (f.minimum > f.maximum)
        fail (where + ": minimum > maximum");
      if (const std::string* s = n.attribute ("scale"))
        if (!real (*s, f.scale) || !std::isfinite (f.scale) || f.scale == 0.0)
          fail (where + ": the scale is not a finite non-zero number");
      if (const std::string* o = n.attribute ("offset"))
        if (!real (*o, f.offset) || !std::isfinite (f.offset))
          fail (where + ": the offset is not a finite number");
      f.has_bounds = min && max;
      const double s = f.type == E57FieldType::Integer ? 1.0 : f.scale;
      const double o = f.type == E57FieldType::Integer ? 0.0 : f.offset;
      f.value_minimum = static_cast<double> (f.minimum) * s + o;
      f.value_maximum = static_cast<double> (f.maximum) * s + o;
      if (s < 0.0)
        std::swap (f.value_minimum, f.value_maximum);
    }
    else if (kind == "Float") {
      f.type = E57FieldType::Float;
      if (const std::string* p = n.attribute ("precision")) {
        if (*p != "single" && *p != "double")
          fail (where + ": precision " + detail::quote (*p) +
                " is neither single nor double");
        f.single_precision = *p == "single";
      }
      double lo = 0.0, hi = 0.0;
      if ((min && !real (*min, lo)) || (max && !real (*max, hi)))
        fail (where + ": minimum or maximum is not a number");
      f.has_bounds = min && max && std::isfinite (lo) && std::isfinite (hi) && lo <= hi;
      f.value_minimum = lo;
      f.value_maximum = hi;
    }
    else if (kind == "String")
      fail (where + ": String elements in point records are not supported");
    else
      fail (where + ": unknown type " + detail::quote (kind));
    return f;
  }

  E57ScanInfo
  scan (const XmlNode& node, std::size_t index) const
  {
    E57ScanInfo s;
    const std::string where = "data3D scan " + std::to_string (index);
    s.name = text (node, "name");
    s.guid = text (node, "guid");
    if (const XmlNode* pose = node.child ("pose")) {
      const XmlNode* r = pose->child ("rotation");
      const XmlNode* t = pose->child ("translation");
      if (r) {
        Eigen::Quaterniond q (number (r, "w", 0.0),
                              number (r, "x", 0.0),
                              number (r, "y", 0.0),
                              number (r, "z", 0.0));
        const double norm = q.norm();
        if (!std::isfinite (norm) || norm < 1e-12)
          fail (where + ": the pose rotation is not a unit quaternion");
        s.rotation = q.normalized();
      }
      if (t)
        s.translation = Eigen::Vector3d (
            number (t, "x", 0.0), number (t, "y", 0.0), number (t, "z", 0.0));
      if (!s.translation.allFinite())
        fail (where + ": the pose translation is not finite");
    }
    if (const XmlNode* limits = node.child ("intensityLimits")) {
      s.has_intensity_limits = true;
      s.intensity_minimum = number (limits, "intensityMinimum", 0.0);
      s.intensity_maximum = number (limits, "intensityMaximum", 0.0);
    }
    if (const XmlNode* limits = node.child ("colorLimits")) {
      s.has_color_limits = true;
      const char* channels[] = {"Red", "Green", "Blue"};
      for (int c = 0; c < 3; ++c) {
        const std::string name = std::string ("color") + channels[c];
        s.color_minimum[c] = number (limits, name + "Minimum", 0.0);
        s.color_maximum[c] = number (limits, name + "Maximum", 255.0);
      }
    }
    const XmlNode* points = node.child ("points");
    const std::string* type = points ? points->attribute ("type") : nullptr;
    if (!points || !type || *type != "CompressedVector")
      fail (where + " has no points CompressedVector");
    const std::string* offset = points->attribute ("fileOffset");
    const std::string* count = points->attribute ("recordCount");
    std::int64_t o = 0, n = 0;
    if (!offset || !count || !integer (*offset, o) || !integer (*count, n) || o < 0 ||
        n < 0)
      fail (where + ": fileOffset or recordCount is missing or not a non-negative "
                    "integer");
    s.file_offset = static_cast<std::uint64_t> (o);
    s.record_count = static_cast<std::uint64_t> (n);
    const XmlNode* prototype = points->child ("prototype");
    if (!prototype)
      fail (where + ": the points have no prototype");
    flatten (*prototype, 0, s.prototype);
    const auto has = [&s] (const char* name) {
      for (const auto& f : s.prototype)
        if (f.name == name)
          return true;
      return false;
    };
    if (!(has ("cartesianX") && has ("cartesianY") && has ("cartesianZ")) &&
        !(has ("sphericalRange") && has ("sphericalAzimuth") &&
          has ("sphericalElevation")))
      fail (where + ": the prototype has neither cartesianX/Y/Z nor "
                    "sphericalRange/Azimuth/Elevation");
    return s;
  }

private:
  std::string path_;
};
} // namespace

std::vector<E57ScanInfo>
parseE57Xml (const std::string& xml,
             const std::string& path,
             std::string* coordinate_metadata)
{
  const Parser p (path);
  Builder b;
  std::unique_ptr<XML_ParserStruct, void (*) (XML_Parser)> parser (
      XML_ParserCreate (nullptr), XML_ParserFree);
  if (!parser)
    throw std::bad_alloc();
  b.parser = parser.get();
  XML_SetUserData (parser.get(), &b);
  XML_SetElementHandler (parser.get(), onStart, onEnd);
  XML_SetCharacterDataHandler (parser.get(), onText);
  if (xml.size() > static_cast<std::size_t> (std::numeric_limits<int>::max()))
    p.fail ("larger than 2 GiB");
  if (XML_Parse (parser.get(), xml.data(), static_cast<int> (xml.size()), XML_TRUE) !=
      XML_STATUS_OK) {
    if (!b.error.empty())
      p.fail (b.error);
    p.fail (std::string ("line ") +
            std::to_string (XML_GetCurrentLineNumber (parser.get())) + ": " +
            XML_ErrorString (XML_GetErrorCode (parser.get())));
  }
  if (b.root.children.size() != 1 || b.root.children[0]->name != "e57Root")
    p.fail ("no e57Root element");
  const XmlNode& root = *b.root.children[0];
  if (coordinate_metadata)
    *coordinate_metadata = p.text (root, "coordinateMetadata");
  std::vector<E57ScanInfo> scans;
  if (const XmlNode* data3d = root.child ("data3D"))
    for (const auto& c : data3d->children)
      scans.push_back (p.scan (*c, scans.size()));
  return scans;
}
} // namespace io
} // namespace pcl_ext
