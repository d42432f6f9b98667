/*
 * pcl_ext_tiles segment_profiles: curve fitting over the parts.
 */
#include "profile_curve_steps.h"

#include <pcl_ext/segmentation/profile_graph.h>
#include <pcl_ext/tiling/tile_results.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>

namespace pcl_ext {
namespace apps {
namespace {
/** A point's scores in a part's "scores" file: evaluated, turn, rms, noise, turn
 * sigma. */
constexpr std::size_t kScoreBytes = 1 + 4 * sizeof (float);

std::string
endsName (std::size_t stack)
{
  return "profiles_ends_" + std::to_string (stack);
}

/** Read a part's whole file into \a bytes. */
bool
readWhole (const std::string& path, std::vector<unsigned char>& bytes)
{
  bytes.clear();
  std::FILE* file = std::fopen (path.c_str(), "rb");
  if (!file) {
    std::cerr << "Error: " << path << " is missing: that part has not run.\n";
    return false;
  }
  unsigned char buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread (buffer, 1, sizeof (buffer), file)) > 0)
    bytes.insert (bytes.end(), buffer, buffer + n);
  const bool ok = !std::ferror (file);
  std::fclose (file);
  if (!ok)
    std::cerr << "Error: cannot read " << path << ".\n";
  return ok;
}

/** The scores of a part's points from its file (as many as \a points). */
bool
readScores (const std::string& path, std::size_t points, profiles::CurveScores& scores)
{
  std::vector<unsigned char> bytes;
  if (!readWhole (path, bytes))
    return false;
  if (bytes.size() != points * kScoreBytes) {
    std::cerr << "Error: " << path << " is broken (not one score per point).\n";
    return false;
  }
  scores.evaluated.resize (points);
  scores.turn.resize (points);
  scores.rms.resize (points);
  scores.noise.resize (points);
  scores.turn_sigma.resize (points);
  for (std::size_t k = 0; k < points; ++k) {
    const unsigned char* r = bytes.data() + k * kScoreBytes;
    scores.evaluated[k] = r[0];
    std::memcpy (&scores.turn[k], r + 1, sizeof (float));
    std::memcpy (&scores.rms[k], r + 5, sizeof (float));
    std::memcpy (&scores.noise[k], r + 9, sizeof (float));
    std::memcpy (&scores.turn_sigma[k], r + 13, sizeof (float));
  }
  return true;
}

/** The global indices of a part's points. */
bool
readIndices (const std::string& workdir,
             std::size_t stack,
             std::size_t part,
             std::vector<std::uint64_t>& indices)
{
  pcl::PointCloud<pcl::PointXYZ> unused;
  return readProfilePart (
      profilePartPath (workdir, stack, part, "points"), indices, unused);
}
} // namespace

bool
scorePartCurves (const ProfileFrame& frame,
                 const ProfileParts& parts,
                 const ProfileOptions& options,
                 const PartPass& pass,
                 const std::string& workdir,
                 unsigned int threads,
                 std::size_t i)
{
  std::size_t stack, part;
  std::vector<std::uint64_t> indices;
  ProfilePartSegmentation<pcl::PointXYZ> seg;
  if (!setUpPart (
          frame, parts, options, pass, workdir, threads, i, stack, indices, seg))
    return false;
  std::vector<profiles::CurveScores> scores;
  std::vector<std::vector<ProfilePartSegmentation<pcl::PointXYZ>::Edge>> chains;
  if (!seg.computeCurveScores (scores, chains) || scores.size() != 1) {
    std::cerr << "Error: the curve scores of part " << i << " failed (see the message "
              << "above).\n";
    return false;
  }
  const auto& s = scores[0];
  std::vector<unsigned char> bytes (indices.size() * kScoreBytes);
  for (std::size_t k = 0; k < indices.size(); ++k) {
    unsigned char* r = bytes.data() + k * kScoreBytes;
    r[0] = s.evaluated[k];
    std::memcpy (r + 1, &s.turn[k], sizeof (float));
    std::memcpy (r + 5, &s.rms[k], sizeof (float));
    std::memcpy (r + 9, &s.noise[k], sizeof (float));
    std::memcpy (r + 13, &s.turn_sigma[k], sizeof (float));
  }
  parts.locate (i, stack, part);
  return writePartFile (
      profilePartPath (workdir, stack, part, "scores"), bytes.data(), bytes.size());
}

bool
findCurveEnds (const tiling::TilePlan& plan,
               const ProfileFrame& frame,
               const ProfileParts& parts,
               const ProfileOptions& options,
               const std::string& workdir,
               std::vector<double>& junction_tolerances)
{
  junction_tolerances.assign (parts.firsts.size(), 0.0);
  // The settings the parts ran with, for the rule's tolerances.
  ProfilePartSegmentation<pcl::PointXYZ> settings;
  options.apply (settings, 1);
  if (frame.spacing > 0.0)
    settings.setPointSpacing (frame.spacing);
  std::vector<std::uint64_t> indices;
  profiles::CurveScores scores;
  for (std::size_t s = 0; s < parts.firsts.size(); ++s) {
    // The medians over every part of the stack: the untiled pipeline's values.
    std::vector<float> rms, noise;
    for (std::size_t p = 0; p < parts.firsts[s].size(); ++p) {
      if (!readIndices (workdir, s, p, indices) ||
          !readScores (
              profilePartPath (workdir, s, p, "scores"), indices.size(), scores))
        return false;
      for (std::size_t k = 0; k < indices.size(); ++k)
        if (scores.evaluated[k]) {
          rms.push_back (scores.rms[k]);
          noise.push_back (scores.noise[k]);
        }
    }
    const profiles::CurveEndRule rule =
        settings.getCurveEndRule (profiles::upperMedian (std::move (rms)),
                                  profiles::upperMedian (std::move (noise)));
    junction_tolerances[s] = rule.junction_tolerance;
    if (!tiling::TileResults::create (workdir, plan.getTotalPoints(), endsName (s)))
      return false;
    std::vector<std::uint32_t> ends;
    for (std::size_t p = 0; p < parts.firsts[s].size(); ++p) {
      if (!readIndices (workdir, s, p, indices) ||
          !readScores (
              profilePartPath (workdir, s, p, "scores"), indices.size(), scores))
        return false;
      ends.assign (indices.size(), 0);
      for (std::size_t k = 0; k < indices.size(); ++k)
        ends[k] =
            profiles::isCurveEnd (scores, k, rule, options.max_turn_deg * M_PI / 180.0);
      if (!tiling::TileResults::write (workdir, indices, ends, endsName (s)))
        return false;
    }
  }
  return true;
}

bool
joinPartCurves (const ProfileFrame& frame,
                const ProfileParts& parts,
                const ProfileOptions& options,
                const PartPass& pass,
                const std::vector<double>& junction_tolerances,
                const std::string& workdir,
                unsigned int threads,
                std::size_t i)
{
  std::size_t stack, part;
  std::vector<std::uint64_t> indices;
  ProfilePartSegmentation<pcl::PointXYZ> seg;
  if (!setUpPart (
          frame, parts, options, pass, workdir, threads, i, stack, indices, seg))
    return false;
  // The part's points' curve ends: its stack's own, and whether any stack ends a
  // curve there.
  const std::size_t m = indices.size();
  std::vector<std::uint8_t> own (m, 0), breakpoints (m, 0);
  std::vector<std::uint32_t> flags;
  for (std::size_t s = 0; s < parts.firsts.size(); ++s) {
    if (!tiling::TileResults::readAt (workdir, indices, flags, endsName (s)))
      return false;
    for (std::size_t k = 0; k < m; ++k) {
      const bool end = flags[k] == 1;
      breakpoints[k] = breakpoints[k] || end;
      if (s == stack)
        own[k] = end;
    }
  }
  std::vector<std::vector<ProfilePartSegmentation<pcl::PointXYZ>::Edge>> edges;
  std::vector<std::uint8_t> out;
  if (!seg.computeCurveJoins (
          {own}, breakpoints, {junction_tolerances[stack]}, edges, out) ||
      edges.size() != 1) {
    std::cerr << "Error: the curve joins of part " << i << " failed (see the message "
              << "above).\n";
    return false;
  }
  std::vector<std::uint64_t> links, absorbed;
  for (const auto& e : edges[0]) {
    links.push_back (indices[e.source]);
    links.push_back (indices[e.target]);
  }
  for (std::size_t k = 0; k < m; ++k)
    if (out[k] && !breakpoints[k])
      absorbed.push_back (indices[k]);
  parts.locate (i, stack, part);
  return writePartFile (profilePartPath (workdir, stack, part, "absorbed"),
                        absorbed.data(),
                        absorbed.size() * sizeof (std::uint64_t)) &&
         writePartFile (profilePartPath (workdir, stack, part, "links"),
                        links.data(),
                        links.size() * sizeof (std::uint64_t));
}

bool
labelCurveSegments (const tiling::TilePlan& plan,
                    const ProfileParts& parts,
                    const std::string& workdir,
                    JoinedParts& joined)
{
  const std::uint64_t total = plan.getTotalPoints();
  std::vector<std::uint8_t> breakpoints (total, 0);
  std::vector<std::uint32_t> flags;
  for (std::size_t s = 0; s < parts.firsts.size(); ++s) {
    for (std::size_t p = 0; p < parts.firsts[s].size(); ++p) {
      std::vector<unsigned char> bytes;
      if (!readWhole (profilePartPath (workdir, s, p, "absorbed"), bytes))
        return false;
      for (std::size_t k = 0; k + sizeof (std::uint64_t) <= bytes.size();
           k += sizeof (std::uint64_t)) {
        std::uint64_t i;
        std::memcpy (&i, bytes.data() + k, sizeof (i));
        if (i >= total) {
          std::cerr << "Error: part " << p << " of stack " << s
                    << "'s absorbed points are broken.\n";
          return false;
        }
        breakpoints[i] = 1;
      }
    }
    for (std::uint64_t first = 0; first < total; first += 1 << 20) {
      const std::size_t n =
          static_cast<std::size_t> (std::min<std::uint64_t> (1 << 20, total - first));
      if (!tiling::TileResults::read (workdir, first, n, flags, endsName (s)))
        return false;
      for (std::size_t k = 0; k < n; ++k)
        if (flags[k] == 1)
          breakpoints[first + k] = 1;
    }
  }
  flags = std::vector<std::uint32_t>();
  // The edges read from the parts' links each time the labelling asks, a part at a
  // time, stack after stack in the order of their profiles, as the pipeline lists them.
  bool read = true;
  const auto for_each_edge = [&] (const profiles::EdgeVisitor& visit) {
    for (std::size_t s = 0; read && s < parts.firsts.size(); ++s)
      for (std::size_t p = 0; read && p < parts.firsts[s].size(); ++p)
        read = forEachPartLink (profilePartPath (workdir, s, p, "links"),
                                total,
                                [&visit] (std::uint64_t a, std::uint64_t b) {
                                  visit (static_cast<std::uint32_t> (a),
                                         static_cast<std::uint32_t> (b));
                                });
  };
  std::vector<std::uint32_t> labels;
  profiles::labelSegments (total, for_each_edge, breakpoints, labels);
  breakpoints = std::vector<std::uint8_t>();
  if (!read)
    return false;
  // Each label's first point is its root. The labels are numbered in order of first
  // point, so label l's first point is at or after l: it is kept at labels[l], whose
  // own label has been read by then.
  joined.sets = UnionFind (total);
  std::uint32_t count = 0;
  for (std::uint32_t i = 0; i < total; ++i) {
    const std::uint32_t label = labels[i];
    if (label == count) {
      labels[label] = i;
      ++count;
    }
    joined.sets.unite (i, labels[label]);
  }
  labels = std::vector<std::uint32_t>();
  joined.size.assign (total, 0);
  if (!markFinitePoints (parts, workdir, joined.size))
    return false;
  countComponents (joined);
  return true;
}
} // namespace apps
} // namespace pcl_ext
