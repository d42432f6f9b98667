/*
 * pcl_ext_compare_segmenters: the table, the CSV file and the tile titles.
 */
#include "comparison_report.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace pcl_ext {
namespace compare {
namespace {
std::string
format (const char* pattern, double value)
{
  char buffer[64];
  std::snprintf (buffer, sizeof (buffer), pattern, value);
  return buffer;
}

double
megabytes (std::size_t bytes)
{
  return static_cast<double> (bytes) / (1024.0 * 1024.0);
}

double
unsegmentedFraction (const MethodResult& r)
{
  if (r.evaluated)
    return r.metrics.unsegmented_fraction;
  return r.labels.empty() ? 0.0
                          : static_cast<double> (r.unsegmented) /
                                static_cast<double> (r.labels.size());
}

/** The method with the highest mean best IoU among those of \a library; null if none.
 */
const MethodResult*
best (const std::vector<MethodResult>& results, const std::string& library)
{
  const MethodResult* top = nullptr;
  for (const auto& r : results)
    if (r.ok && r.evaluated && r.library == library &&
        (!top || r.metrics.mean_best_iou > top->metrics.mean_best_iou))
      top = &r;
  return top;
}
} // namespace

void
printTable (const std::vector<MethodResult>& results, bool with_truth)
{
  char line[320];
  if (with_truth)
    std::snprintf (line,
                   sizeof (line),
                   "\n%-15s %-8s %-7s %8s %8s %8s %7s %5s %5s %6s %7s %9s %9s\n",
                   "method",
                   "library",
                   "normals",
                   "segments",
                   "mean IoU",
                   "wtd IoU",
                   "correct",
                   "over",
                   "under",
                   "missed",
                   "unseg",
                   "time s",
                   "peak MB");
  else
    std::snprintf (line,
                   sizeof (line),
                   "\n%-15s %-8s %-7s %8s %7s %9s %9s\n",
                   "method",
                   "library",
                   "normals",
                   "segments",
                   "unseg",
                   "time s",
                   "peak MB");
  std::cout << line;
  for (const auto& r : results) {
    const char* normals = r.needs_normals ? "yes" : "-";
    if (!r.ok) {
      std::snprintf (line,
                     sizeof (line),
                     "%-15s %-8s %-7s %s\n",
                     r.name.c_str(),
                     r.library.c_str(),
                     normals,
                     ("failed: " + r.error).c_str());
      std::cout << line;
      continue;
    }
    const std::string unseg = format ("%.1f %%", 100.0 * unsegmentedFraction (r));
    if (with_truth) {
      const auto& m = r.metrics;
      std::snprintf (
          line,
          sizeof (line),
          "%-15s %-8s %-7s %8zu %8.4f %8.4f %7zu %5zu %5zu %6zu %7s %9.3f %9.1f\n",
          r.name.c_str(),
          r.library.c_str(),
          normals,
          r.segments,
          m.mean_best_iou,
          m.weighted_mean_best_iou,
          m.correct,
          m.over_segmented,
          m.under_segmented,
          m.missed,
          unseg.c_str(),
          r.seconds,
          megabytes (r.peak_bytes));
    }
    else
      std::snprintf (line,
                     sizeof (line),
                     "%-15s %-8s %-7s %8zu %7s %9.3f %9.1f\n",
                     r.name.c_str(),
                     r.library.c_str(),
                     normals,
                     r.segments,
                     unseg.c_str(),
                     r.seconds,
                     megabytes (r.peak_bytes));
    std::cout << line;
  }
  if (!with_truth)
    return;
  const MethodResult* ours = best (results, "pcl_ext");
  const MethodResult* stock = best (results, "PCL");
  const MethodResult* cgal = best (results, "CGAL");
  if (ours && stock)
    std::cout << "\nBest mean best IoU: pcl_ext " << ours->name << " "
              << format ("%.4f", ours->metrics.mean_best_iou) << ", stock PCL "
              << stock->name << " " << format ("%.4f", stock->metrics.mean_best_iou)
              << (cgal ? ", CGAL " + cgal->name + " " +
                             format ("%.4f", cgal->metrics.mean_best_iou)
                       : std::string())
              << ".\n";
}

std::string
makeCsv (const std::vector<MethodResult>& results, bool with_truth)
{
  std::ostringstream csv;
  csv.precision (17);
  csv << "method,library,normals,status,segments,mean_best_iou,weighted_mean_best_iou,"
         "correct,"
         "over_segmented,under_segmented,missed,noise,truth_segments,evaluated_points,"
         "unsegmented_fraction,seconds,peak_memory_bytes\n";
  for (const auto& r : results) {
    csv << r.name << ',' << r.library << ',' << (r.needs_normals ? "yes" : "no") << ','
        << (r.ok ? "ok" : "failed") << ',';
    if (!r.ok) {
      csv << ",,,,,,,,,,,,\n";
      continue;
    }
    csv << r.segments << ',';
    if (with_truth) {
      const auto& m = r.metrics;
      csv << m.mean_best_iou << ',' << m.weighted_mean_best_iou << ',' << m.correct
          << ',' << m.over_segmented << ',' << m.under_segmented << ',' << m.missed
          << ',' << m.noise << ',' << m.num_truth_segments << ',' << m.evaluated_points
          << ',';
    }
    else
      csv << ",,,,,,,,,";
    csv << unsegmentedFraction (r) << ',' << r.seconds << ',' << r.peak_bytes << '\n';
  }
  return csv.str();
}

std::string
tileTitle (const MethodResult& r, bool with_truth)
{
  std::string title = r.name + " (" + r.library + ")\n";
  if (with_truth)
    title += "IoU " + format ("%.3f", r.metrics.mean_best_iou) + ", ";
  return title + std::to_string (r.segments) +
         (r.segments == 1 ? " segment, " : " segments, ") + format ("%.2f", r.seconds) +
         " s";
}
} // namespace compare
} // namespace pcl_ext
