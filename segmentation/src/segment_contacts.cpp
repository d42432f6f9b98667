/*
 * pcl_ext: segment contacts and the merges of interleaved coplanar segments.
 */
#include <pcl_ext/common/covariance.h>
#include <pcl_ext/segmentation/segment_contacts.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

namespace pcl_ext {
void
SegmentContacts::addPoints (std::uint32_t segment, const PlaneSums& sums)
{
  if (segment != 0 && sums.size() != 0)
    planes_[segment].add (sums);
}

void
SegmentContacts::addContacts (std::uint32_t from, std::uint32_t to, std::size_t count)
{
  if (from != 0 && to != 0 && from != to && count != 0)
    contacts_[{from, to}] += count;
}

void
SegmentContacts::add (const SegmentContacts& other)
{
  for (const auto& [label, s] : other.planes_)
    planes_[label].add (s);
  for (const auto& [pair, count] : other.contacts_)
    contacts_[pair] += count;
}

namespace {
struct SegmentPlaneFit {
  std::size_t n = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  EigenDecomposition eigen;
};

SegmentPlaneFit
segmentPlaneOf (const SegmentContacts::PlaneSums& s)
{
  SegmentPlaneFit p;
  p.n = s.finish (p.covariance, p.centroid);
  if (p.n == 0)
    return p;
  computeEigenDecomposition (p.covariance, p.eigen);
  return p;
}

// Mean squared distance of the points of b to the plane of a.
double
meanSquaredPlaneDistance (const SegmentPlaneFit& b, const SegmentPlaneFit& a)
{
  const Eigen::Vector3d n = a.eigen.normal();
  const double offset = n.dot (b.centroid - a.centroid);
  return n.dot (b.covariance * n) + offset * offset;
}
} // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>>
mergeInterleavedCoplanarSegments (const SegmentContacts& contacts,
                                  const CoplanarMergeCriteria& criteria,
                                  std::size_t* merges)
{
  // The segments by rank in label order (any labels, however large), so that the
  // smaller rank is the smaller label.
  std::vector<std::uint32_t> labels;
  for (const auto& [label, s] : contacts.planes())
    labels.push_back (label);
  const std::size_t size = labels.size();
  const auto rankOf = [&labels] (std::uint32_t label) -> std::ptrdiff_t {
    const auto it = std::lower_bound (labels.begin(), labels.end(), label);
    return it != labels.end() && *it == label ? it - labels.begin() : -1;
  };
  // The groups, under their smallest rank: plane sums and contacts both ways.
  std::vector<SegmentContacts::PlaneSums> sums (size);
  std::vector<std::map<std::uint32_t, std::size_t>> out (size), in (size);
  std::vector<std::uint32_t> version (size, 0);
  {
    std::size_t r = 0;
    for (const auto& [label, s] : contacts.planes())
      sums[r++] = s;
  }
  for (const auto& [pair, count] : contacts.contacts()) {
    const std::ptrdiff_t a = rankOf (pair.first), b = rankOf (pair.second);
    if (a < 0 || b < 0 || a == b)
      continue;
    out[static_cast<std::size_t> (a)][static_cast<std::uint32_t> (b)] += count;
    in[static_cast<std::size_t> (b)][static_cast<std::uint32_t> (a)] += count;
  }
  const double min_cos = std::cos (criteria.max_angle);
  // The share of the smaller group's points in contact with the larger, where the two
  // meet the other criteria; else a negative value.
  const auto score = [&] (std::uint32_t a, std::uint32_t b) {
    const SegmentPlaneFit pa = segmentPlaneOf (sums[a]), pb = segmentPlaneOf (sums[b]);
    const SegmentPlaneFit* large = &pa;
    const SegmentPlaneFit* small = &pb;
    std::uint32_t from = b, to = a;
    if (pb.n > pa.n || (pb.n == pa.n && b < a)) {
      std::swap (large, small);
      std::swap (from, to);
    }
    if (small->n == 0)
      return -1.0;
    const auto c = out[from].find (to);
    const double fraction = c == out[from].end() ? 0.0
                                                 : static_cast<double> (c->second) /
                                                       static_cast<double> (small->n);
    const double residual =
        std::sqrt (std::max ({large->eigen.values (0), small->eigen.values (0), 0.0}));
    const double distance = std::sqrt (meanSquaredPlaneDistance (*small, *large));
    const bool small_is_plane =
        small->eigen.values (1) >= 0.05 * small->eigen.values (2);
    const double cosine = std::abs (small->eigen.normal().dot (large->eigen.normal()));
    if (fraction < criteria.min_contact_fraction ||
        !(distance <= criteria.distance_factor * residual) ||
        (small_is_plane && cosine < min_cos))
      return -1.0;
    return fraction;
  };
  struct Candidate {
    double fraction;
    std::uint32_t a, b, version_a, version_b;
    bool
    operator<(const Candidate& o) const
    {
      // Highest share first; ties by the ranks (the labels' order), so the order is the
      // same in every run.
      if (fraction != o.fraction)
        return fraction < o.fraction;
      if (a != o.a)
        return a > o.a;
      return b > o.b;
    }
  };
  std::priority_queue<Candidate> queue;
  const auto consider = [&] (std::uint32_t a, std::uint32_t b) {
    if (a > b)
      std::swap (a, b);
    const double f = score (a, b);
    if (f >= 0.0)
      queue.push ({f, a, b, version[a], version[b]});
  };
  for (std::uint32_t a = 0; a < size; ++a)
    for (const auto& [b, count] : out[a])
      if (a < b || !out[b].count (a))
        consider (a, b);
  std::vector<std::uint32_t> parent (size);
  std::iota (parent.begin(), parent.end(), 0u);
  std::size_t count = 0;
  while (!queue.empty()) {
    const Candidate c = queue.top();
    queue.pop();
    if (parent[c.a] != c.a || parent[c.b] != c.b || version[c.a] != c.version_a ||
        version[c.b] != c.version_b)
      continue;
    // Merge b into a (a < b: the group keeps its smallest rank, so label).
    const std::uint32_t a = c.a, b = c.b;
    parent[b] = a;
    sums[a].add (sums[b]);
    for (const auto& [z, n] : out[b])
      if (z != a) {
        out[a][z] += n;
        in[z][a] += n;
        in[z].erase (b);
      }
    for (const auto& [z, n] : in[b])
      if (z != a) {
        in[a][z] += n;
        out[z][a] += n;
        out[z].erase (b);
      }
    out[a].erase (b);
    in[a].erase (b);
    out[b].clear();
    in[b].clear();
    ++version[a];
    ++count;
    std::vector<std::uint32_t> partners;
    for (const auto& [z, n] : out[a])
      partners.push_back (z);
    for (const auto& [z, n] : in[a])
      partners.push_back (z);
    std::sort (partners.begin(), partners.end());
    partners.erase (std::unique (partners.begin(), partners.end()), partners.end());
    for (const auto z : partners)
      consider (a, z);
  }
  if (merges)
    *merges = count;
  const auto root = [&parent] (std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x];
    return x;
  };
  // The groups numbered 1, 2, ... in the order of their smallest labels.
  std::vector<std::uint32_t> renumbered (size, 0);
  std::uint32_t next = 0;
  for (std::uint32_t r = 0; r < size; ++r)
    if (parent[r] == r)
      renumbered[r] = ++next;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> result (size);
  for (std::uint32_t r = 0; r < size; ++r)
    result[r] = {labels[r], renumbered[root (r)]};
  return result;
}
} // namespace pcl_ext
