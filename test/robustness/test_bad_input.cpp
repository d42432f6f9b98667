/*
 * The bad-input matrix of the cloud-processing classes (test/README.md): every class
 * against every kind of bad cloud, bad indices, bad parameter and bad normals that
 * applies to it.
 *
 * Each run is one test named BadInput/Matrix.Run/<Class>_<Input>. The expected
 * outcomes:
 * - Refused: empty output and a PCL_ERROR from pcl_ext (or PCL's own, naming the
 * class); nothing thrown;
 * - Computed: one output per index, the documented "no result" (NaN, label 0, an empty
 *   neighbourhood, no segment) for every non-finite point, and a result for some finite
 * one;
 * - Degenerate: as Computed, but every point may get "no result" (collinear points have
 * no tangent plane);
 * - NoneFound: empty output without a PCL_ERROR from pcl_ext: a segmenter that finds
 *   nothing to segment (no plane among too few points) has not failed;
 * - Ran: registration only: align() returns, converged or not, with a finite
 * transformation.
 *
 * The harness and the inputs are in bad_input.h, the rows of each module (the classes,
 * the inputs that apply to them and the outcomes they expect) in
 * bad_input_<module>.cpp.
 */
#include "bad_input.h"

#include <pcl/common/point_tests.h>

#include <gtest/gtest.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

using namespace pcl_ext::test::bad_input;

namespace {
/** The rows of the matrix, in the order of the cases. */
std::vector<Subject>
subjects ()
{
  std::vector<Subject> s;
  addFeatureSubjects (s);
  addClassificationSubjects (s);
  addSegmentationSubjects (s);
  addCrfSubjects (s);
  addRegistrationSubjects (s);
  return s;
}

const std::vector<Subject>&
allSubjects ()
{
  static const std::vector<Subject> s = subjects();
  return s;
}

struct Case {
  std::size_t subject;
  Bad bad;
};

std::vector<Case>
allCases ()
{
  std::vector<Case> cases;
  const auto& s = allSubjects();
  for (std::size_t i = 0; i < s.size(); ++i)
    for (const auto& entry : kBadNames)
      if (s[i].applies.count (entry.first))
        cases.push_back ({i, entry.first});
  return cases;
}

class Matrix : public ::testing::TestWithParam<Case> {};

TEST_P (Matrix, Run)
{
  const Subject& subject = allSubjects()[GetParam().subject];
  const Bad bad = GetParam().bad;
  const auto it = subject.expectations.find (bad);
  const Expect expect =
      it != subject.expectations.end() ? it->second : defaultExpectation (bad);
  const Input in = inputFor (bad);
  if (subject.prepare)
    subject.prepare();

  ::testing::internal::CaptureStderr();
  const Outcome o = subject.run (in);
  const std::string log = ::testing::internal::GetCapturedStderr();

  switch (expect) {
  case Expect::Refused:
    EXPECT_FALSE (o.produced) << "bad input accepted";
    EXPECT_EQ (o.size, 0u);
    EXPECT_TRUE (log.find ("[pcl_ext::") != std::string::npos ||
                 log.find (subject.name) != std::string::npos)
        << "no PCL_ERROR from pcl_ext or naming the class; stderr: " << log;
    break;
  case Expect::Computed:
  case Expect::Degenerate: {
    ASSERT_TRUE (o.produced) << "stderr: " << log;
    const auto indices = indicesOf (in);
    ASSERT_EQ (o.size, indices.size());
    ASSERT_EQ (o.no_result.size(), indices.size());
    std::size_t results = 0;
    for (std::size_t r = 0; r < indices.size(); ++r) {
      if (!pcl::isFinite ((*in.cloud)[indices[r]]))
        EXPECT_TRUE (o.no_result[r])
            << "non-finite point " << indices[r] << " got a result";
      results += o.no_result[r] ? 0 : 1;
    }
    if (expect == Expect::Computed)
      EXPECT_GT (results, 0u) << "no point got a result";
    break;
  }
  case Expect::NoneFound:
    EXPECT_FALSE (o.produced);
    EXPECT_EQ (o.size, 0u);
    EXPECT_EQ (log.find ("[pcl_ext::"), std::string::npos)
        << "reported as an error: " << log;
    break;
  case Expect::Ran:
    EXPECT_TRUE (o.finite_transform);
    break;
  }
}

/** Names a case in gtest's messages (otherwise printed as the struct's bytes). */
void
PrintTo (const Case& c, std::ostream* os)
{
  *os << allSubjects()[c.subject].name << " on " << kBadNames.at (c.bad);
}

std::string
caseName (const ::testing::TestParamInfo<Case>& info)
{
  return allSubjects()[info.param.subject].name + "_" + kBadNames.at (info.param.bad);
}

INSTANTIATE_TEST_SUITE_P (BadInput, Matrix, ::testing::ValuesIn (allCases()), caseName);
} // namespace
