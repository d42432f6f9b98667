/*
 * pcl_ext_tiles segment_profiles: curve fitting over the parts (Sithole & Mapurisa,
 * section 4.1.2), in three passes and two joins (ProfilePartSegmentation).
 */
#pragma once

#include "profile_part_steps.h"

#include <pcl_ext/segmentation/profile_pipeline.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_ext {
namespace apps {
/** \brief First pass: part \a i's scores (each point's, in the part's order) into its
 * "scores" file. \return false (message printed) on error */
bool
scorePartCurves (const ProfileFrame& frame,
                 const ProfileParts& parts,
                 const ProfileOptions& options,
                 const PartPass& pass,
                 const std::string& workdir,
                 unsigned int threads,
                 std::size_t i);

/** \brief Each stack's curve end rule from the medians of its evaluated points'
 * residuals and noise over every part (an exact selection, as the untiled pipeline's),
 * and each point's own curve ends in each stack in a file per stack at the points'
 * indices. \return false (message printed) when a part's scores are missing or broken
 */
bool
findCurveEnds (const tiling::TilePlan& plan,
               const ProfileFrame& frame,
               const ProfileParts& parts,
               const ProfileOptions& options,
               const std::string& workdir,
               std::vector<double>& junction_tolerances);

/** \brief Last pass: part \a i's chains and the curves followed across its junctions,
 * given every stack's curve ends, into its "links" file as pairs of global indices, and
 * the points the joins absorb into its "absorbed" file. \return false (message printed)
 * on error */
bool
joinPartCurves (const ProfileFrame& frame,
                const ProfileParts& parts,
                const ProfileOptions& options,
                const PartPass& pass,
                const std::vector<double>& junction_tolerances,
                const std::string& workdir,
                unsigned int threads,
                std::size_t i);

/** \brief The segments of every part's edges and every stack's breakpoints
 * (profiles::labelSegments over all points, the edges read from the parts' files each
 * time it asks; about 12 bytes a point and the edges of the points the waves join), as
 * joined components for saveSegments. \return false (message printed) on error */
bool
labelCurveSegments (const tiling::TilePlan& plan,
                    const ProfileParts& parts,
                    const std::string& workdir,
                    JoinedParts& joined);
} // namespace apps
} // namespace pcl_ext
