// DefaultVocabularyPath() alone in this file: DSLAM_DEFAULT_VOCABULARY (an absolute path, set in
// CMakeLists.txt) is on this file's command line only.

#include "dslam/place_recognition/vocabulary.h"

namespace dslam {

std::string DefaultVocabularyPath() { return DSLAM_DEFAULT_VOCABULARY; }

}  // namespace dslam
