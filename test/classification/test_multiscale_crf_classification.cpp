/*
 * Tests of MultiscaleCrfClassification, the multi-scale CRF (Lim & Suter 2008) as a PCL
 * class.
 */
#include "../features/crf_test_clouds.h"

#include <pcl_ext/classification/multiscale_crf_classification.h>

#include <gtest/gtest.h>

TEST (MultiscaleCrfClassification, PclClassOnPointTypes)
{
  // Two classes on the floor-and-wall cloud, through the PCL wrapper.
  std::vector<std::uint32_t> truth;
  const auto xyz = crf_test::floorAndWall (0.05, 0.003, &truth);
  pcl_ext::MultiscaleCrfClassification<pcl::PointXYZ> crf;
  crf.setClassNames ({{1, "floor"}, {2, "wall"}});
  crf.setNumberOfThreads (2);
  ASSERT_TRUE (crf.train ({xyz}, {truth}));
  const auto test = crf_test::floorAndWall (0.05, 0.003, nullptr, 99);
  crf.setInputCloud (test);
  pcl::PointCloud<pcl::Label> labels;
  crf.classify (labels);
  ASSERT_EQ (labels.size(), test->size());
  std::size_t correct = 0;
  for (std::size_t i = 0; i < labels.size(); ++i)
    correct += labels[i].label == truth[i];
  EXPECT_GT (static_cast<double> (correct) / labels.size(), 0.97);
  std::vector<pcl::PointIndices> classes;
  crf.extract (classes);
  ASSERT_EQ (classes.size(), 2u);
  EXPECT_EQ (classes[0].indices.size() + classes[1].indices.size(), test->size());
  EXPECT_EQ (crf.getProbabilities().rows(), static_cast<Eigen::Index> (test->size()));
  // Indices: only the indexed points are labelled.
  crf.setIndices (pcl::make_shared<pcl::Indices> (pcl::Indices{0, 1, 2, 3, 4000}));
  crf.classify (labels);
  EXPECT_EQ (labels.size(), 0u) << "five points are too few for super-voxels";
  // A model trained on xyz refuses nothing on a colour type; a colour model needs
  // colour.
  pcl_ext::MultiscaleCrfClassification<pcl::PointXYZ> untrained;
  untrained.setInputCloud (test);
  untrained.classify (labels);
  EXPECT_TRUE (labels.empty());
}
