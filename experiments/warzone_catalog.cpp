#include "warzone_catalog.hpp"

namespace spinhash::experiment {
namespace {

constexpr const char* kBodyDir = "components/bodies/";
constexpr const char* kPropDir = "components/prop/";

struct BodyClass {
  const char* bodies[4];
  const char* wheels;
  const char* half_tracks;
  const char* tracks;
  const char* hover;
};

// stats/body.json, warzone2100-data 4.3.3 (Body7ABT alone has its own hover skirt).
const BodyClass kBodyClasses[] = {
    {{"drlbod01", "drlbod02", "drlbod03", "drlbod04"}, "prlwhl1", "prlhtr1", "prltrk1", "prlhov1"},
    {{"drmbod05", "drmbod06", "drmbod07", "drmbod08"}, "prmwhl1", "prmhtr2", "prmtrk2", "prmhov1"},
    {{"drhbod09", "drhbod10", "drhbod11", "drhbod12"}, "prhwhl1", "prhhtr3", "prhtrk3", "prhhov1"},
};
constexpr const char* kBody7 = "drmbod07";
constexpr const char* kBody7Hover = "prmhov2";

struct OnePiece {
  const char* stem;
  const char* klass;
  const char* group = "";  // where its class has none ("": its class's)
};
// One-piece vehicles of the scavenger faction: the buggies and the trike
// are unarmoured runabouts of a jeep's size, so light vehicles. (The
// hover bodies above stay in no group: a hovercraft is none of them.)
const OnePiece kOnePiece[] = {{"exjeep", "suv"},
                              {"exjeeprk", "suv"},
                              {"exbuggy", "other", "light"},
                              {"exbugrk", "other", "light"},
                              {"extrike", "other", "light"},
                              {"exschool", "bus"},
                              {"exfire", "truck"}};

std::string pie(const char* dir, const std::string& stem) { return std::string(dir) + stem + ".pie"; }

}  // namespace

std::vector<WarzoneVehicle> warzone_vehicles() {
  std::vector<WarzoneVehicle> out;
  for (const BodyClass& c : kBodyClasses)
    for (const char* body : c.bodies) {
      struct Propulsion {
        const char* name;
        const char* part;
        const char* klass;
      };
      const Propulsion props[] = {{"wheels", c.wheels, "apc"},
                                  {"halftracks", c.half_tracks, "tracked"},
                                  {"tracks", c.tracks, "tracked"},
                                  {"hover", std::string(body) == kBody7 ? kBody7Hover : c.hover, "other"}};
      for (const Propulsion& p : props)
        out.push_back({"wz-" + std::string(body) + "-" + p.name,
                       {pie(kBodyDir, body), pie(kPropDir, p.part)},
                       p.klass,
                       ""});
    }
  for (const OnePiece& v : kOnePiece)
    out.push_back({"wz-" + std::string(v.stem), {pie(kBodyDir, v.stem)}, v.klass, v.group});
  return out;
}

bool is_texture_variant(const std::string& stem) {
  auto ends = [&](const std::string& s) {
    return stem.size() > s.size() && stem.compare(stem.size() - s.size(), s.size(), s) == 0;
  };
  return ends("_col") || ends("_nex");
}

}  // namespace spinhash::experiment
