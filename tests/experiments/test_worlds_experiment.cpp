// Smoke test of `spinhash-experiment worlds` on two generated mini-worlds
// (one member of each procedural family each) and a piece of catalog
// clutter: the per-scan CSV, read by column name, holds every scan under
// every condition with each database, a left-out database never names a
// model of the scanned world, and the summary has its tables.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "csv_columns.hpp"
#include "geometry_test_support.hpp"
#include "spinhash/vehicle_class.hpp"

namespace {

using spinhash::host::test::CsvColumns;
using spinhash::host::test::read_bytes;
using spinhash::host::test::TempDir;
using spinhash::host::test::write_bytes;

constexpr int kFamilies = 8;                 // the procedural fleet's: two members of each make 16 vehicles
const std::string kOtherLight = "sedan-01";  // catalogued as class other, group light

// A unit box standing on z = 0 (a crate-sized non-vehicle).
const char* kBoxObj =
    "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\n"
    "v -0.5 -0.5 1\nv 0.5 -0.5 1\nv 0.5 0.5 1\nv -0.5 0.5 1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
    "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

// Generates 16 fleet members into DIR/meshes and catalogs them: the -00
// members as world "north", the -01 members as "south", plus the box as
// clutter of source "mini-structure". One saloon is catalogued as class
// "other" in group "light" (a class that spans the groups, with the
// vehicle's own group given); the others' group cells are empty (their
// class's).
void make_mini_worlds(const TempDir& dir) {
  const std::string meshes = dir.file("meshes");
  const std::string gen =
      "'" SPINHASH_TEST_BINARY "' generate --count 16 -o '" + meshes + "' 2> '" + dir.file("gen.txt") + "'";
  REQUIRE(std::system(gen.c_str()) == 0);
  write_bytes(meshes + "/box-a.obj", kBoxObj);
  std::string catalog = "name,class,group,source\n";
  for (const auto& f : std::filesystem::directory_iterator(meshes)) {
    const std::string stem = f.path().stem().string();
    if (f.path().extension() != ".obj" || stem == "box-a") continue;
    const std::string family = stem.substr(0, stem.find('-'));
    const bool other = stem == kOtherLight;
    catalog += stem + "," + (other ? "other" : family) + "," + (other ? "light" : "") + "," +
               (stem.back() == '0' ? "north" : "south") + "\n";
  }
  catalog += "box-a,,,mini-structure\n";
  write_bytes(meshes + "/catalog.csv", catalog);
}

int run_worlds(const TempDir& dir, const std::string& args) {
  // Quick databases: the smoke test checks the experiment's plumbing, not the calibration.
  const std::string cmd = "'" SPINHASH_EXPERIMENT_BINARY "' worlds --fleet 0 --no-calibration " + args +
                          " --out '" + dir.file("out") + "' 2> '" + dir.file("stderr.txt") + "'";
  return std::system(cmd.c_str());
}

}  // namespace

TEST_CASE("experiment worlds leaves each of two mini-worlds out") {
  TempDir dir("experiment-worlds");
  make_mini_worlds(dir);
  const std::string args = "--catalog '" + dir.file("meshes") +
                           "' --clutter-source mini-structure --scene-clutter 1 --vehicle-sized-clutter 1 "
                           "--clutter-scans 1 --scans-per-world 1 --min-scans 1 --threads 2";
  REQUIRE(run_worlds(dir, args + " --quiet") == 0);
  const CsvColumns csv(read_bytes(dir.file("out/per_scan.csv")));
  for (const char* column : {"world",
                             "object",
                             "kind",
                             "true_class",
                             "true_group",
                             "condition",
                             "database",
                             "first_model",
                             "first_world",
                             "model_right",
                             "model_confident",
                             "class_right",
                             "class_confident",
                             "group_right",
                             "group_confident",
                             "vehicle_confident",
                             "vehicle_evidence",
                             "group_evidence",
                             "class_evidence",
                             "model_evidence",
                             "level",
                             "density",
                             "ground"})
    CHECK_MESSAGE(csv.has(column), column);
  // 16 vehicles x 4 conditions x 2 databases, then 4 scene pieces, 4 vehicle-sized ones and the box
  // once (sparse).
  REQUIRE(csv.rows() == 2u * kFamilies * 4u * 2u + 9u);
  std::map<std::string, int> per_condition;
  std::set<std::string> clutter_kinds;
  int vehicle_rows = 0, known_right = 0, with_evidence = 0, other_light_first = 0;
  for (size_t i = 0; i < csv.rows(); ++i) {
    // The recognizer's answer level: a chain of flags from the vehicle level down.
    const std::string level = csv.cell(i, "level");
    CHECK((level == "none") == (csv.cell(i, "vehicle_confident") == "0"));
    if (level == "group" || level == "class" || level == "model")
      CHECK(csv.cell(i, "group_confident") == "1");
    if (level == "class" || level == "model") CHECK(csv.cell(i, "class_confident") == "1");
    if (level == "model") CHECK(csv.cell(i, "model_confident") == "1");
    with_evidence += csv.cell(i, "vehicle_evidence").empty() ? 0 : 1;
    const std::string condition = csv.cell(i, "condition");
    if (csv.cell(i, "kind") != "vehicle") {
      clutter_kinds.insert(csv.cell(i, "kind"));
      CHECK(condition == "sparse");
      CHECK(csv.cell(i, "database") == "all");
      CHECK(csv.cell(i, "true_class").empty());
      continue;
    }
    ++vehicle_rows;
    ++per_condition[condition];
    // The truth a group answer is judged against is the vehicle's own group.
    const std::string object = csv.cell(i, "object");
    if (object == kOtherLight) {
      CHECK(csv.cell(i, "true_class") == "other");
      CHECK(csv.cell(i, "true_group") == "light");
    } else {
      // Without a group cell, the class's group from the one class list.
      const std::string family = object.substr(0, object.find('-'));
      spinhash::VehicleClass c = spinhash::VehicleClass::kUnclassified;
      REQUIRE(spinhash::parse_vehicle_class(family.c_str(), &c));
      CHECK(csv.cell(i, "true_class") == family);
      CHECK(csv.cell(i, "true_group") == spinhash::vehicle_group_name(spinhash::vehicle_group_of(c)));
      CHECK(csv.cell(i, "true_group") != "none");
    }
    if (csv.cell(i, "group_confident") == "1")
      CHECK((csv.cell(i, "group_right") == "1") == (csv.cell(i, "first_group") == csv.cell(i, "true_group")));
    const std::string world = csv.cell(i, "world");
    CHECK((world == "north" || world == "south"));
    const std::string database = csv.cell(i, "database");
    if (database == "left-out") {
      // The database of the other world: never the scanned world's models.
      CHECK(csv.cell(i, "first_world") != world);
      CHECK(csv.cell(i, "model_right") == "0");
    } else {
      REQUIRE(database == "all");
      known_right += csv.cell(i, "model_right") == "1" ? 1 : 0;
    }
    // The catalog's group is built into the model: ranked first, the
    // "other" vehicle puts the light group first.
    if (csv.cell(i, "first_model") == kOtherLight) {
      ++other_light_first;
      CHECK(csv.cell(i, "first_group") == "light");
    }
    // A survey's density in the sparse condition; 0.10 m (212 points per m^2) elsewhere.
    const double density = csv.number(i, "density");
    if (condition == "sparse")
      CHECK((density >= 20.0 && density <= 30.0));
    else
      CHECK(csv.number(i, "spacing_m") == doctest::Approx(0.1));
    CHECK(csv.cell(i, "ground") == (condition == "ground" || condition == "sparse" ? "1" : "0"));
  }
  CHECK(vehicle_rows == 2 * kFamilies * 4 * 2);
  CHECK(with_evidence > kFamilies * 2);  // the vehicle level's evidence of every posed answer
  for (const char* c : {"clean", "ground", "no-ground", "sparse"})
    CHECK(per_condition[c] == 2 * kFamilies * 2);
  CHECK(clutter_kinds == std::set<std::string>{"tree", "wall", "crate", "building", "shed", "container",
                                               "bush", "heap", "mini-structure"});
  // With its model in the database, most clean and ground-free scans name the vehicle first.
  CHECK(known_right > kFamilies * 2);
  CHECK(other_light_first > 0);
  const std::string summary = read_bytes(dir.file("out/summary.md"));
  for (const char* heading :
       {"# Leave one world out", "## Targets", "## north", "## south", "## All worlds pooled",
        "## Sparse: light vehicles, clutter", "| without-north | 8 |", "| all | 16 |"})
    CHECK_MESSAGE(summary.find(heading) != std::string::npos, heading);
  CHECK(std::filesystem::exists(dir.file("out/databases/without-south.shdb")));

  // Again on the databases just built: no build, the same answers.
  REQUIRE(run_worlds(dir, args + " --reuse-databases") == 0);
  CHECK(read_bytes(dir.file("stderr.txt")).find("building") == std::string::npos);
  const CsvColumns again(read_bytes(dir.file("out/per_scan.csv")));
  REQUIRE(again.rows() == csv.rows());
  for (size_t i = 0; i < csv.rows(); ++i) {
    CHECK(again.cell(i, "object") == csv.cell(i, "object"));
    CHECK(again.cell(i, "first_model") == csv.cell(i, "first_model"));
  }
}

TEST_CASE("experiment worlds refuses a single world and a catalog with an unknown class or group") {
  TempDir dir("experiment-worlds-errors");
  make_mini_worlds(dir);
  const std::string catalog = read_bytes(dir.file("meshes/catalog.csv"));
  // Runs the experiment on `edited` (the catalog with one edit) and
  // expects it refused with `message` on stderr.
  const auto refused = [&](const std::string& edited, const char* message) {
    write_bytes(dir.file("meshes/catalog.csv"), edited);
    CHECK(run_worlds(dir, "--catalog '" + dir.file("meshes") + "' --scene-clutter 0") != 0);
    CHECK_MESSAGE(read_bytes(dir.file("stderr.txt")).find(message) != std::string::npos, message);
  };
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string edited = catalog;
    edited.replace(edited.find(from), from.size(), to);
    return edited;
  };
  // Every vehicle in one world: nothing to leave out.
  std::string one = catalog;
  for (size_t p; (p = one.find(",south")) != std::string::npos;) one.replace(p, 6, ",north");
  refused(one, "at least two worlds");
  // A class that is not in the class list.
  refused(replaced(",sedan,", ",saloon,"), "'saloon' is not a vehicle class");
  // A group that is not in the group list.
  refused(replaced(",other,light,", ",other,medium,"), "'medium' is not a vehicle group");
  // A group that contradicts the class's own.
  refused(replaced(",sedan,,", ",sedan,heavy,"), "class 'sedan' is in group 'light'");
  CHECK(!std::filesystem::exists(dir.file("out/summary.md")));
}
