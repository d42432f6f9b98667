/*
 * pcl_ext: an app's result written next to the input's fields, in the input's frame.
 */
#pragma once

#include <pcl_ext/apps/command_line.h>
#include <pcl_ext/io/point_file.h>

#include <pcl/PCLPointCloud2.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief The field an app writes its per-point result to: `-output_field NAME`
 * (default per app, e.g. `lv_class`), and for classifications `-asprs` (also write
 * the result as ASPRS codes into a LAS output's standard Classification).
 *
 * An input field of the same name is never overwritten unless the user named it with
 * -output_field. In a LAS output the field becomes an extra-bytes dimension.
 */
class ResultField {
public:
  /** \param[in] default_name the field's default name \param[in] what the result, for
   * the help text ("class", "segment id") \param[in] asprs_note when not empty, the app
   * offers -asprs: what it does; when empty, -asprs is accepted only to be refused with
   * \a refusal \param[in] refusal why -asprs is refused (apps without ASPRS codes) */
  ResultField (std::string default_name,
               std::string what,
               std::string asprs_note,
               std::string refusal = "");

  /** \brief Declare -output_field and -asprs on \a cl. */
  void
  addTo (CommandLine& cl);

  /** \brief The command line of an app that writes the input's points again with its
   * result: the positionals `input` (any point file, kInputFormats) and `output`
   * (kOutputFormats), then -output_field and -asprs as addTo(). */
  void
  addTo (CommandLine& cl, std::string& input, std::string& output);

  /** \brief Before any work: the output's format can be written
   * (io::canWritePointFile), its folder and those of the \a optional outputs are
   * writable, and -asprs is usable (offered by the app, .las output). Prints the reason
   * and returns false otherwise. */
  bool
  checkOutput (const std::string& output,
               std::initializer_list<std::string> optional = {}) const;

  /** \brief After loading: when \a input already has the field and the user did not
   * name it, the result goes to the first free name \a name_2, \a name_3, ... (the
   * input's field is kept; a note says where the result is). A field the user named is
   * replaced. \return true (kept for the callers' checks) */
  bool
  checkInput (const io::PointFile& input, const std::string& input_path);

  /** \brief \a cloud with \a values (one per point) in the result field (uint32).
   * \return false (message printed) on a size mismatch */
  bool
  attach (pcl::PCLPointCloud2& cloud, const std::vector<std::uint32_t>& values) const;

  /** \brief The input's points and fields with \a values (one per point) in the result
   * field, written to \a path (saveOutput). \return false (message printed) on a size
   * mismatch or a write error */
  bool
  save (const std::string& path,
        const io::PointFile& input,
        const std::vector<std::uint32_t>& values) const;

  const std::string&
  name () const
  {
    return name_;
  }

  bool
  asprs () const
  {
    return asprs_;
  }

private:
  std::string name_, what_, asprs_note_, refusal_;
  bool asprs_ = false;
  const CommandLine* cl_ = nullptr;
};

/** \brief Write \a cloud (coordinates relative to input.origin) to \a path with
 * io::savePointFile, in \a input's frame and (LAS) with its header, with a "Saving"
 * timing line. */
bool
saveOutput (const std::string& path,
            const pcl::PCLPointCloud2& cloud,
            const io::PointFile& input);

/** \brief The ASPRS standard class (LAS 1.4 R15, table 17) of a class name: ground 2,
 * low / medium / high vegetation 3 / 4 / 5 (vegetation, tree: 5), building / facade /
 * roof / wall 6, noise 7, water 9, rail 10, road 11, wire 14, transmission tower 15,
 * bridge 17; -1 for a name with no code (matched case-insensitively on words). */
int
asprsClass (const std::string& name);
/** \brief The segmenters' result field: segment ids in 'segment' (1.. by decreasing
 * size, 0: none); -asprs refused, segment ids being no classes. */
ResultField
segmentIdField ();
} // namespace apps
} // namespace pcl_ext
