// A recognizer or scene configuration as one line of text, every field of
// the field lists by its key ("mode bran; seed 1; ...; ground.enabled on;
// ..."; "top_n 5; window_core 32; ..."): the experiments' summaries and the
// survey's settings key.
#pragma once
#include <string>

#include "spinhash/config.hpp"
#include "spinhash/scene.hpp"

namespace spinhash::host {

// `with_mode` false: every field but the mode (the experiments list their modes).
std::string config_text(const RecognizerConfig& c, bool with_mode = true);
// The scene's own fields (scene_fields.h); its recognizer is config_text's.
std::string config_text(const SceneConfig& c);

}  // namespace spinhash::host
