// The table of validation studies: one line per study.
#include "curvsph/validation/study.hpp"

namespace curvsph {

const std::vector<Study>& validation_studies() {
  static const std::vector<Study> studies = {
  };
  return studies;
}

}  // namespace curvsph
