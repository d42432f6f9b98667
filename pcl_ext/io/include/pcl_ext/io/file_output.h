/*
 * pcl_ext: output files that are never left half-written.
 */
#pragma once

#include <functional>
#include <initializer_list>
#include <string>

namespace pcl_ext {
namespace io {
/** \brief Write \a path through \a writer without ever leaving a partial file.
 *
 * \a writer receives a temporary path in the same folder (so the final rename stays on
 * one file system) and returns true on success. On success the temporary file is
 * renamed over \a path; on failure (false, an exception, or no file written) it is
 * removed, \a path is left as it was, and an error naming \a path goes to stderr.
 * \return true when \a path now holds the new content
 */
bool
writeFileAtomically (
    const std::string& path,
    const std::function<bool (const std::string& temporary_path)>& writer);

/** \brief A file written under a temporary name in its folder and moved to its path
 * only when complete: the machinery of writeFileAtomically, for writers that write a
 * file over many calls (e.g. LasWriter). Destroyed before commit(), it removes the
 * temporary file. */
class AtomicFileOutput {
public:
  AtomicFileOutput() = default;
  ~AtomicFileOutput();
  AtomicFileOutput (const AtomicFileOutput&) = delete;
  AtomicFileOutput&
  operator= (const AtomicFileOutput&) = delete;

  /** \brief Choose the temporary path for \a path (checkWritable first). \return false
   * (an error naming \a path) when \a path cannot be written */
  bool
  open (const std::string& path);

  /** \brief Where to write until commit(). */
  const std::string&
  getTemporaryPath () const
  {
    return temporary_;
  }

  /** \brief Rename the temporary file over the path. \return false (the temporary file
   * removed, an error naming the path) when it does not exist or cannot be renamed */
  bool
  commit ();

  /** \brief Remove the temporary file; the path is left as it was. */
  void
  abandon ();

private:
  std::string path_, temporary_;
};

/** \brief Write text to \a path atomically (see writeFileAtomically). */
bool
writeTextFile (const std::string& path, const std::string& text);

/** \brief Whether a file can be created in the folder of \a path (checked before long
 * work so that an unwritable output fails fast). Prints an error naming the path when
 * it cannot. */
bool
checkWritable (const std::string& path);

/** \brief checkWritable for the output an app always writes and for each optional
 * output that was asked for (an empty path is one that was not). */
bool
checkOutputsWritable (const std::string& output,
                      std::initializer_list<std::string> optional);

/** \brief Lower-case extension of \a path without the dot ("pcd", "ply"), or "". */
std::string
fileExtension (const std::string& path);
} // namespace io
} // namespace pcl_ext
