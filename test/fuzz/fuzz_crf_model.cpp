/*
 * Fuzz target: the multi-scale CRF model file (MultiscaleCrfModel::loadModel).
 *
 * A model that loads is written back with toText() and must load again to the same
 * text.
 */
#include <pcl_ext/classification/crf_model.h>

#include <pcl/console/print.h>

#include "fuzz_input_file.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static pcl_ext_fuzz::InputFile file;
  static const bool quiet = [] {
    pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
    return true;
  }();
  (void)quiet;
  pcl_ext::MultiscaleCrfModel model;
  if (!model.loadModel (file.write (data, size))) {
    pcl_ext_fuzz::check (!model.isTrained(),
                         "a failed load leaves the model untrained");
    return 0;
  }
  using pcl_ext_fuzz::check;
  check (model.isTrained(), "a loaded model is trained");
  check (model.getClassLabels().size() >= 2, "a model has two classes or more");
  const std::string text = model.toText();
  pcl_ext::MultiscaleCrfModel again;
  check (again.parseModel (text, "round trip"), "a loaded model's text loads again");
  check (again.toText() == text, "the round trip keeps the model");
  return 0;
}
