/*
 * pcl_ext: output files that are never left half-written.
 */
#include <pcl_ext/io/file_output.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

namespace pcl_ext {
namespace io {
namespace {
std::string
folderOf (const std::string& path)
{
  const auto slash = path.find_last_of ('/');
  if (slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : path.substr (0, slash);
}

std::string
temporaryPathFor (const std::string& path)
{
  // Same folder (rename must not cross file systems), hidden, unique per process and
  // call.
  static std::mt19937_64 rng (static_cast<std::uint64_t> (::getpid()) *
                              0x9E3779B97F4A7C15ull);
  const auto slash = path.find_last_of ('/');
  const std::string name = slash == std::string::npos ? path : path.substr (slash + 1);
  const std::string ext = fileExtension (path);
  char tag[17];
  std::snprintf (tag, sizeof (tag), "%016llx", static_cast<unsigned long long> (rng()));
  // Keep the extension last: writers such as PCL's choose the format by it.
  return folderOf (path) + "/." + name + "." + tag + ".tmp" +
         (ext.empty() ? "" : "." + ext);
}

bool
fileExists (const std::string& path)
{
  struct stat st;
  return ::stat (path.c_str(), &st) == 0 && S_ISREG (st.st_mode);
}
} // namespace

std::string
fileExtension (const std::string& path)
{
  const auto slash = path.find_last_of ('/');
  const auto dot = path.find_last_of ('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
      dot + 1 == path.size())
    return "";
  std::string ext = path.substr (dot + 1);
  std::transform (ext.begin(), ext.end(), ext.begin(), [] (unsigned char c) {
    return static_cast<char> (std::tolower (c));
  });
  return ext;
}

bool
checkWritable (const std::string& path)
{
  if (path.empty()) {
    PCL_ERROR ("[pcl_ext::io::checkWritable] empty output path.\n");
    return false;
  }
  struct stat st;
  if (::stat (path.c_str(), &st) == 0 && S_ISDIR (st.st_mode)) {
    PCL_ERROR ("[pcl_ext::io::checkWritable] cannot write %s: it is a folder.\n",
               path.c_str());
    return false;
  }
  const std::string folder = folderOf (path);
  if (::access (folder.c_str(), W_OK | X_OK) != 0) {
    PCL_ERROR (
        "[pcl_ext::io::checkWritable] cannot write %s: folder %s does not exist or is "
        "not writable.\n",
        path.c_str(),
        folder.c_str());
    return false;
  }
  return true;
}

bool
checkOutputsWritable (const std::string& output,
                      std::initializer_list<std::string> optional)
{
  if (!checkWritable (output))
    return false;
  for (const auto& path : optional)
    if (!path.empty() && !checkWritable (path))
      return false;
  return true;
}

AtomicFileOutput::~AtomicFileOutput() { abandon(); }

bool
AtomicFileOutput::open (const std::string& path)
{
  abandon();
  if (!checkWritable (path))
    return false;
  path_ = path;
  temporary_ = temporaryPathFor (path);
  return true;
}

bool
AtomicFileOutput::commit()
{
  if (!temporary_.empty() && fileExists (temporary_) &&
      std::rename (temporary_.c_str(), path_.c_str()) == 0) {
    temporary_.clear();
    return true;
  }
  abandon();
  PCL_ERROR ("[pcl_ext::io] could not write %s (disk full or folder not writable); "
             "nothing was written.\n",
             path_.c_str());
  return false;
}

void
AtomicFileOutput::abandon()
{
  if (!temporary_.empty())
    std::remove (temporary_.c_str());
  temporary_.clear();
}

bool
writeFileAtomically (const std::string& path,
                     const std::function<bool (const std::string&)>& writer)
{
  AtomicFileOutput output;
  if (!output.open (path))
    return false;
  bool ok = false;
  try {
    ok = writer (output.getTemporaryPath());
  }
  catch (const std::exception& e) {
    PCL_ERROR ("[pcl_ext::io::writeFileAtomically] writing %s failed: %s\n",
               path.c_str(),
               e.what());
    ok = false;
  }
  if (ok)
    return output.commit();
  output.abandon();
  PCL_ERROR ("[pcl_ext::io::writeFileAtomically] could not write %s (disk full or "
             "folder not writable); nothing was written.\n",
             path.c_str());
  return false;
}

bool
writeTextFile (const std::string& path, const std::string& text)
{
  return writeFileAtomically (path, [&text] (const std::string& temporary) {
    std::ofstream out (temporary, std::ios::binary);
    out << text;
    out.close();
    return static_cast<bool> (out);
  });
}
} // namespace io
} // namespace pcl_ext
