// A configuration as one line of text (host/config/config_text.hpp), the
// survey's settings key: every scene field is named, and a change to any
// one of them changes the text.
#include <doctest/doctest.h>

#include <string>

#include "config/config_text.hpp"
#include "spinhash/scene_fields.h"

using spinhash::SceneConfig;
using spinhash::host::config_text;

TEST_CASE("a scene configuration's text names every field of scene_fields.h and moves with each") {
  const SceneConfig defaults;
  const std::string text = config_text(defaults);
  CHECK(config_text(SceneConfig{}) == text);
  int fields = 0;
#define SPINHASH_SCENE_FIELD_CHECK(kind, name, lo, hi, flag, help)        \
  {                                                                       \
    INFO("field " #name);                                                 \
    CHECK(text.find(#name " ") != std::string::npos);                     \
    SceneConfig changed;                                                  \
    changed.name = static_cast<decltype(changed.name)>(changed.name + 1); \
    CHECK(config_text(changed) != text);                                  \
    ++fields;                                                             \
  }
  SPINHASH_SCENE_CONFIG_FIELDS(SPINHASH_SCENE_FIELD_CHECK)
#undef SPINHASH_SCENE_FIELD_CHECK
  CHECK(fields > 30);
  CHECK(text.find("terrain_noise_gap 1") != std::string::npos);
}
