// A recognizer setting by its field name (host/config/config_assign.hpp): the
// experiments' --set and the target runner's FIELD=VALUE.
#include <doctest/doctest.h>

#include <string>

#include "config/config_assign.hpp"
#include "spinhash/presets.hpp"

using spinhash::RecognizerConfig;
using spinhash::host::assign_config_field;

TEST_CASE("config_assign: numbers and booleans by name, within the field's range") {
  RecognizerConfig c;
  std::string error;
  CHECK(assign_config_field("max_bucket_scan=512", &c, &error));
  CHECK(c.max_bucket_scan == 512u);
  CHECK(assign_config_field("query_cloud_voxel=0.12", &c, &error));
  CHECK(c.query_cloud_voxel == 0.12f);
  CHECK(assign_config_field("seed=18446744073709551615", &c, &error));
  CHECK(c.seed == 18446744073709551615ull);
  CHECK(assign_config_field("refine_poses=0", &c, &error));
  CHECK_FALSE(c.refine_poses);
  const RecognizerConfig before = c;
  for (const char* bad :
       {"max_bucket_scan=0", "max_bucket_scan=-1", "max_bucket_scan=12x", "top_w=", "top_w", "sigma=1e9",
        "sigma=nan", "no_such_field=1", "refine_poses=2", "mode=1", "viewpoint=1"}) {
    CAPTURE(bad);
    error.clear();
    CHECK_FALSE(assign_config_field(bad, &c, &error));
    CHECK_FALSE(error.empty());
  }
  CHECK(c.max_bucket_scan == before.max_bucket_scan);
  CHECK(c.top_w == before.top_w);
}

TEST_CASE("config_assign: preset=flight sets the preset's fields") {
  RecognizerConfig c;
  std::string error;
  c.seed = 9;
  CHECK(assign_config_field("preset=flight", &c, &error));
  CHECK(c.max_features == spinhash::kFlightMaxFeatures);
  CHECK(c.query_cloud_voxel == spinhash::kFlightQueryVoxel);
  CHECK(c.seed == 9u);
  CHECK_FALSE(assign_config_field("preset=fast", &c, &error));
}
