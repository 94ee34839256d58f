// experiment worlds: summary.md, per world and condition against the
// targets: as unknown vehicles (the world left out of the database) the
// class and group flags' precision and how often they are raised, and
// every model flag a false alarm; with the world's models in, right first
// and the model flag's precision and recall; in the sparse condition the
// light vehicles named light and the clutter that gets a confident answer.
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>

#include "output_dir.hpp"
#include "spinhash/vehicle_class.hpp"
#include "stats.hpp"
#include "worlds_data.hpp"

namespace spinhash::experiment {
namespace {

struct Share {
  uint64_t k = 0, n = 0;
  void add(bool hit) {
    ++n;
    k += hit ? 1u : 0u;
  }
};

// A share's target: at least or at most `value`.
struct Target {
  double value = 0.0;
  bool at_most = false;
  const char* text = "";
};

const Target kClassFlag{0.98, false, "`class_confident` right when raised, at least 98 %"};
const Target kGroupFlag{0.99, false, "group flag right when raised, at least 99 %"};
const Target kUnknownModelFlag{0.005, true, "model flag on vehicles not in the database, at most 0.5 %"};
const Target kRightFirst{0.97, false, "right first with the world's models in, at least 97 %"};
const Target kModelFlag{0.99, false, "`confident` right when raised, at least 99 %"};
const Target kFlagged{0.85, false, "right answers flagged `confident`, at least 85 %"};
const Target kLight{0.60, false, "sparse: light vehicles left out confidently light, at least 60 %"};
const Target kClutter{0.0, true, "sparse: clutter with a confident answer at any level: none"};

enum class Verdict { kNone, kMet, kMissed };

Verdict verdict(const Share& s, const Target& t) {
  if (s.n == 0) return Verdict::kNone;
  const double p = static_cast<double>(s.k) / static_cast<double>(s.n);
  return (t.at_most ? p <= t.value : p >= t.value) ? Verdict::kMet : Verdict::kMissed;
}

std::string percent(double p) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f %%", 100.0 * p);
  return b;
}

// "97.5 % (117/120, 93.0-99.1 %)", "-" for n = 0.
std::string share_text(const Share& s) {
  if (s.n == 0) return "-";
  const ShareInterval ci = wilson_interval(s.k, s.n);
  char b[96];
  std::snprintf(b, sizeof b, "%.1f %% (%llu/%llu, %.1f-%.1f)", 100.0 * s.k / s.n,
                static_cast<unsigned long long>(s.k), static_cast<unsigned long long>(s.n), 100.0 * ci.lo,
                100.0 * ci.hi);
  return b;
}

// One (world, condition) cell's verdict per target, for the targets table.
struct Cell {
  std::string where;
  Share share;
};
using Cells = std::map<const Target*, std::vector<Cell>>;

std::string judged(const Share& s, const Target& t, const std::string& where, Cells* cells) {
  (*cells)[&t].push_back(Cell{where, s});
  const Verdict v = verdict(s, t);
  return share_text(s) + (v == Verdict::kMissed ? " **missed**" : "");
}

using RecordFilter = std::function<bool(const WorldsRecord&)>;

struct UnknownTally {
  Share class_first, class_raised, class_flag, group_raised, group_flag, model_raised;
};
struct KnownTally {
  Share right_first, raised, flag, flagged;
};

UnknownTally tally_unknown(const WorldsRun& run, const RecordFilter& keep) {
  UnknownTally t;
  for (const WorldsRecord& r : run.records) {
    if (r.clutter || r.database != WorldsDatabase::kLeftOut || !keep(r)) continue;
    const WorldsJudgement j = judge(run, r);
    t.class_first.add(j.class_right);
    t.class_raised.add(r.answer.class_confident);
    if (r.answer.class_confident) t.class_flag.add(j.class_right);
    t.group_raised.add(r.answer.group_confident);
    if (r.answer.group_confident) t.group_flag.add(j.group_right);
    t.model_raised.add(r.answer.model_confident);
  }
  return t;
}

KnownTally tally_known(const WorldsRun& run, const RecordFilter& keep) {
  KnownTally t;
  for (const WorldsRecord& r : run.records) {
    if (r.clutter || r.database != WorldsDatabase::kAll || !keep(r)) continue;
    const WorldsJudgement j = judge(run, r);
    t.right_first.add(j.model_right);
    t.raised.add(r.answer.model_confident);
    if (r.answer.model_confident) t.flag.add(j.model_right);
    if (j.model_right) t.flagged.add(r.answer.model_confident);
  }
  return t;
}

std::string count_text(const Share& s) { return s.n == 0 ? "-" : percent(double(s.k) / double(s.n)); }

// The two tables of a world (world < 0: every world pooled).
std::string world_tables(const WorldsRun& run, int world, Cells* cells) {
  const WorldSet& set = *run.set;
  const std::string name = world < 0 ? "all worlds" : set.worlds[static_cast<size_t>(world)];
  auto in_world = [&](const WorldsRecord& r) {
    return world < 0 || set.vehicles[r.object].world == set.worlds[static_cast<size_t>(world)];
  };
  std::ostringstream s;
  s << "Left out (the database of the other worlds' vehicles):\n\n"
    << "| condition | scans | class first right | class flag raised | class flag right (>= 98 %) "
       "| group flag raised | group flag right (>= 99 %) | model flag raised, every one false (<= 0.5 %) |\n"
    << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (uint32_t c = 0; c < run.conditions.size(); ++c) {
    const UnknownTally t =
        tally_unknown(run, [&](const WorldsRecord& r) { return r.condition == c && in_world(r); });
    const std::string where = name + ", " + run.conditions[c].name;
    s << "| " << run.conditions[c].name << " | " << t.class_first.n << " | " << count_text(t.class_first)
      << " | " << count_text(t.class_raised) << " | " << judged(t.class_flag, kClassFlag, where, cells)
      << " | " << count_text(t.group_raised) << " | " << judged(t.group_flag, kGroupFlag, where, cells)
      << " | " << judged(t.model_raised, kUnknownModelFlag, where, cells) << " |\n";
  }
  s << "\nIn the database (every world's vehicles):\n\n"
    << "| condition | scans | right first (>= 97 %) | confident raised | confident right (>= 99 %) "
       "| right answers flagged (>= 85 %) |\n"
    << "| --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (uint32_t c = 0; c < run.conditions.size(); ++c) {
    const KnownTally t =
        tally_known(run, [&](const WorldsRecord& r) { return r.condition == c && in_world(r); });
    const std::string where = name + ", " + run.conditions[c].name;
    s << "| " << run.conditions[c].name << " | " << t.right_first.n << " | "
      << judged(t.right_first, kRightFirst, where, cells) << " | " << count_text(t.raised) << " | "
      << judged(t.flag, kModelFlag, where, cells) << " | " << judged(t.flagged, kFlagged, where, cells)
      << " |\n";
  }
  return s.str();
}

int sparse_condition(const WorldsRun& run) {
  for (uint32_t c = 0; c < run.conditions.size(); ++c)
    if (run.conditions[c].name == "sparse") return static_cast<int>(c);
  return -1;
}

std::string sparse_section(const WorldsRun& run, Cells* cells) {
  const int sparse = sparse_condition(run);
  if (sparse < 0) return "";
  const WorldSet& set = *run.set;
  const uint32_t light = static_cast<uint32_t>(VehicleGroup::kLight);
  std::ostringstream s;
  s << "## Sparse: light vehicles, clutter\n\n"
    << "Light vehicles (" << run.conditions[static_cast<size_t>(sparse)].text
    << ") confidently a light vehicle:\n\n"
    << "| world | light vehicles | scans | left out (>= 60 %) | in the database |\n"
    << "| --- | ---: | ---: | ---: | ---: |\n";
  for (int w = -1; w < static_cast<int>(set.worlds.size()); ++w) {
    Share db[2];
    uint32_t vehicles = 0;
    for (uint32_t v = 0; v < set.vehicles.size(); ++v)
      vehicles += (w < 0 || set.vehicles[v].world == set.worlds[static_cast<size_t>(w)]) &&
                          set.vehicles[v].group() == VehicleGroup::kLight
                      ? 1u
                      : 0u;
    for (const WorldsRecord& r : run.records) {
      if (r.clutter || r.condition != static_cast<uint32_t>(sparse)) continue;
      if (w >= 0 && set.vehicles[r.object].world != set.worlds[static_cast<size_t>(w)]) continue;
      if (judge(run, r).true_group != light) continue;
      db[r.database == WorldsDatabase::kLeftOut ? 0 : 1].add(r.answer.at_least(AnswerLevel::kGroup) &&
                                                             r.answer.group == light);
    }
    if (vehicles == 0) continue;
    const std::string name = w < 0 ? "**all worlds**" : set.worlds[static_cast<size_t>(w)];
    Cells pooled;  // the pooled row is shown, not counted as a cell
    s << "| " << name << " | " << vehicles << " | " << db[0].n << " | "
      << judged(db[0], kLight, name, w < 0 ? &pooled : cells) << " | " << share_text(db[1]) << " |\n";
  }
  s << "\nClutter, recognised with the database of every world's vehicles (" << run.clutter_scans
    << " scans of each piece); a confident answer at any level is a false alarm:\n\n"
    << "| source | kind | pieces | scans | confident at any level (none) | at model / class / group / "
       "vehicle "
       "level |\n"
    << "| --- | --- | ---: | ---: | ---: | --- |\n";
  std::vector<std::pair<std::string, std::string>> kinds;
  for (const ClutterObject& c : set.clutter)
    if (std::find(kinds.begin(), kinds.end(), std::make_pair(c.source, c.kind)) == kinds.end())
      kinds.emplace_back(c.source, c.kind);
  Share all;
  for (const auto& [source, kind] : kinds) {
    Share any;
    std::map<std::string, uint32_t> levels;
    uint32_t pieces = 0;
    for (const ClutterObject& c : set.clutter) pieces += c.source == source && c.kind == kind ? 1u : 0u;
    for (const WorldsRecord& r : run.records) {
      if (!r.clutter || set.clutter[r.object].source != source || set.clutter[r.object].kind != kind)
        continue;
      any.add(r.answer.any_confident());
      all.add(r.answer.any_confident());
      levels[r.answer.level] += 1;
    }
    s << "| " << source << " | " << kind << " | " << pieces << " | " << any.n << " | "
      << judged(any, kClutter, source + " " + kind, cells) << " | " << levels["model"] << " / "
      << levels["class"] << " / " << levels["group"] << " / " << levels["vehicle"] << " |\n";
  }
  s << "| **all** | | " << set.clutter.size() << " | " << all.n << " | " << share_text(all) << " | |\n\n";
  return s.str();
}

// Per target: cells met, missed, without data, and the missed ones.
std::string targets_table(const Cells& cells) {
  const Target* order[] = {&kClassFlag, &kGroupFlag, &kUnknownModelFlag, &kRightFirst, &kModelFlag,
                           &kFlagged,   &kLight,     &kClutter};
  std::ostringstream s;
  s << "| target | cells met | missed | no data | the missed |\n| --- | ---: | ---: | ---: | --- |\n";
  for (const Target* t : order) {
    const auto it = cells.find(t);
    if (it == cells.end()) continue;
    uint32_t met = 0, missed = 0, none = 0;
    std::string which;
    for (const Cell& c : it->second) {
      const Verdict v = verdict(c.share, *t);
      met += v == Verdict::kMet ? 1u : 0u;
      none += v == Verdict::kNone ? 1u : 0u;
      if (v != Verdict::kMissed) continue;
      ++missed;
      which += (which.empty() ? "" : "; ") + c.where + ": " + percent(double(c.share.k) / double(c.share.n));
    }
    s << "| " << t->text << " | " << met << " | " << missed << " | " << none << " | " << which << " |\n";
  }
  return s.str();
}

std::string class_counts(const WorldSet& set, uint32_t w) {
  std::map<std::string, uint32_t> n;
  for (uint32_t v : set.vehicles_of(w))
    n[vehicle_class_name(static_cast<uint32_t>(set.vehicles[v].model.vehicle_class))]++;
  std::string out;
  for (const auto& [k, c] : n) out += (out.empty() ? "" : ", ") + std::to_string(c) + " " + k;
  return out;
}

std::string header(const WorldsRun& run) {
  const WorldSet& set = *run.set;
  std::ostringstream s;
  s << "# Leave one world out\n\n"
    << "`" << run.command << "` (spinhash " << run.version << "): " << static_cast<long>(run.seconds + 0.5)
    << " s.\n\n"
    << "Each world's vehicles are scanned and recognised twice from the same scans: with a database of every "
       "other world's vehicles (left out: unknown vehicles, whose classes and groups the database knows from "
       "other worlds' models) and with a database of every world's vehicles (in). Shares are k/n with their "
       "95 % Wilson interval; a target is met or missed on the share; `-`: no scan or no flag raised.\n\n"
    << "| world | vehicles | classes | scans per vehicle and condition |\n| --- | ---: | --- | ---: |\n";
  for (uint32_t w = 0; w < set.worlds.size(); ++w)
    s << "| " << set.worlds[w] << " | " << set.vehicles_of(w).size() << " | " << class_counts(set, w) << " | "
      << run.scans_per_vehicle[w] << " |\n";
  s << "\nConditions (3 views 45 degrees apart at 45 degrees elevation, a random pose):\n\n";
  for (const WorldsCondition& c : run.conditions) s << "- " << c.name << ": " << c.text << "\n";
  s << "\nDatabases (`spinhash build`'s path and options):\n\n"
    << "| database | models | features | MB | build, s |\n| --- | ---: | ---: | ---: | ---: |\n";
  for (const WorldsDatabaseInfo& d : run.databases) {
    char mb[32];
    std::snprintf(mb, sizeof mb, "%.1f", d.bytes / 1e6);
    s << "| " << d.name << " | " << d.models << " | " << d.features << " | " << mb << " | "
      << static_cast<long>(d.seconds + 0.5) << " |\n";
  }
  uint32_t failed = 0;
  for (const WorldsRecord& r : run.records) failed += r.status == Status::kOk ? 0u : 1u;
  s << "\nRecognizer: the library defaults (" << run.recognizer << ").\n\n"
    << "Recognitions without an answer (a status other than ok): " << failed << " of " << run.records.size()
    << ".\n\n";
  return s.str();
}

}  // namespace

bool write_worlds_report(const WorldsRun& run, std::string* error) {
  Cells cells;
  std::ostringstream body;
  for (uint32_t w = 0; w < run.set->worlds.size(); ++w)
    body << "## " << run.set->worlds[w] << " (" << class_counts(*run.set, w) << ")\n\n"
         << world_tables(run, static_cast<int>(w), &cells) << "\n";
  Cells pooled;  // the pooled rows are shown, not counted as cells
  body << "## All worlds pooled\n\n" << world_tables(run, -1, &pooled) << "\n" << sparse_section(run, &cells);
  const std::string summary = header(run) +
                              "## Targets\n\nCells are (world, condition) pairs; the sparse rows "
                              "are per world and per kind of clutter.\n\n" +
                              targets_table(cells) + "\n" + body.str();
  return write_worlds_csv(run, error) && write_text(run.out_dir + "/summary.md", summary, error);
}

}  // namespace spinhash::experiment
