/*
 * pcl_ext: the profile segmentation of a part of a cloud, implementation.
 */
#pragma once

#include <pcl_ext/segmentation/impl/profile_segmentation.hpp>
#include <pcl_ext/segmentation/profile_part_segmentation.h>

#include <pcl/console/print.h>

#include <limits>

namespace pcl_ext {
template <typename PointT>
bool
ProfilePartSegmentation<PointT>::computeLocalGaps (
    std::vector<std::vector<float>>& gaps)
{
  gaps.clear();
  if (!this->local_threshold_) {
    PCL_ERROR ("[pcl_ext::ProfilePartSegmentation::computeLocalGaps] Local thresholds "
               "are off.\n");
    return false;
  }
  profiles::PipelineResult result;
  if (!this->runPipeline (profiles::PipelineStage::LocalGaps, result))
    return false;
  gaps.assign (result.local_gaps.size(),
               std::vector<float> (this->input_->size(),
                                   std::numeric_limits<float>::quiet_NaN()));
  for (std::size_t s = 0; s < result.local_gaps.size(); ++s)
    for (std::size_t i = 0; i < this->points_.size(); ++i)
      gaps[s][this->points_[i]] = result.local_gaps[s][i];
  this->deinitCompute();
  return true;
}

template <typename PointT>
bool
ProfilePartSegmentation<PointT>::computeCurveScores (
    std::vector<profiles::CurveScores>& scores, std::vector<std::vector<Edge>>& chains)
{
  scores.clear();
  chains.clear();
  if (this->method_ != profiles::ProfileMethod::CurveFitting) {
    PCL_ERROR ("[pcl_ext::ProfilePartSegmentation::computeCurveScores] The method is "
               "not curve fitting.\n");
    return false;
  }
  profiles::PipelineResult result;
  if (!this->runPipeline (profiles::PipelineStage::CurveScores, result))
    return false;
  const std::size_t n = this->input_->size();
  scores.resize (result.curve_scores.size());
  for (std::size_t s = 0; s < scores.size(); ++s) {
    auto& out = scores[s];
    const auto& in = result.curve_scores[s];
    out.evaluated.assign (n, 0);
    out.turn.assign (n, 0.f);
    out.rms.assign (n, 0.f);
    out.noise.assign (n, 0.f);
    out.turn_sigma.assign (n, 0.f);
    for (std::size_t i = 0; i < this->points_.size(); ++i) {
      const auto index = static_cast<std::size_t> (this->points_[i]);
      out.evaluated[index] = in.evaluated[i];
      out.turn[index] = in.turn[i];
      out.rms[index] = in.rms[i];
      out.noise[index] = in.noise[i];
      out.turn_sigma[index] = in.turn_sigma[i];
    }
  }
  chains.resize (result.edges.size());
  for (std::size_t s = 0; s < result.edges.size(); ++s) {
    chains[s].reserve (result.edges[s].size());
    for (const auto& e : result.edges[s])
      chains[s].push_back ({this->points_[e.source], this->points_[e.target]});
  }
  this->deinitCompute();
  return true;
}

template <typename PointT>
profiles::CurveEndRule
ProfilePartSegmentation<PointT>::getCurveEndRule (double median_rms,
                                                  double median_noise) const
{
  profiles::PipelineParameters p;
  p.residual_factor = this->residual_factor_;
  // As resolveLengths sets it; before any run, from the settings and the spacing.
  const double threshold = this->used_threshold_ > 0.0 ? this->used_threshold_
                           : this->threshold_ > 0.0
                               ? this->threshold_
                               : this->threshold_factor_ * this->spacing_;
  p.min_residual = 0.1 * threshold;
  p.turn_significance = this->turn_significance_;
  return profiles::curveEndRule (median_rms, median_noise, p);
}

template <typename PointT>
bool
ProfilePartSegmentation<PointT>::computeCurveJoins (
    const std::vector<std::vector<std::uint8_t>>& own_ends,
    const std::vector<std::uint8_t>& breakpoints,
    const std::vector<double>& junction_tolerances,
    std::vector<std::vector<Edge>>& edges,
    std::vector<std::uint8_t>& breakpoints_out)
{
  edges.clear();
  breakpoints_out.clear();
  const char* name = "pcl_ext::ProfilePartSegmentation::computeCurveJoins";
  if (this->method_ != profiles::ProfileMethod::CurveFitting) {
    PCL_ERROR ("[%s] The method is not curve fitting.\n", name);
    return false;
  }
  if (!this->input_ || breakpoints.size() != this->input_->size() ||
      own_ends.size() != junction_tolerances.size()) {
    PCL_ERROR ("[%s] Need one breakpoint flag per input point and a junction tolerance "
               "per stack's curve ends.\n",
               name);
    return false;
  }
  for (const auto& ends : own_ends)
    if (ends.size() != this->input_->size()) {
      PCL_ERROR ("[%s] Need one curve end flag per input point in every stack.\n",
                 name);
      return false;
    }
  this->given_ends_ = own_ends;
  this->given_breakpoints_ = breakpoints;
  this->junction_tolerances_ = junction_tolerances;
  profiles::PipelineResult result;
  const bool ok = this->runPipeline (profiles::PipelineStage::CurveJoins, result);
  this->given_ends_.clear();
  this->given_breakpoints_.clear();
  this->junction_tolerances_.clear();
  if (!ok)
    return false;
  edges.resize (result.edges.size());
  for (std::size_t s = 0; s < result.edges.size(); ++s) {
    edges[s].reserve (result.edges[s].size());
    for (const auto& e : result.edges[s])
      edges[s].push_back ({this->points_[e.source], this->points_[e.target]});
  }
  breakpoints_out.assign (this->input_->size(), 0);
  for (std::size_t i = 0; i < this->points_.size(); ++i)
    breakpoints_out[this->points_[i]] = result.breakpoints[i];
  this->deinitCompute();
  return true;
}
} // namespace pcl_ext

#define PCL_EXT_INSTANTIATE_ProfilePartSegmentation(T)                                 \
  template class pcl_ext::ProfilePartSegmentation<T>;
