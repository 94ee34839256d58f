#include "support/golden_stream_run.hpp"

#include <algorithm>

#include "blob/aligned_bytes.hpp"

namespace spinhash {
namespace test {
namespace {

void keep(void* context, const SceneObject& o, int64_t row, uint32_t col) {
  golden::GoldenObject g{};
  g.row = row;
  g.col = col;
  g.kind = static_cast<uint32_t>(o.kind);
  g.points = o.points;
  g.model = o.ranking_count > 0 ? static_cast<int32_t>(o.ranking[0].model) : -1;
  g.score = o.ranking_count > 0 ? o.ranking[0].score : 0.0f;
  g.confident = o.confident;
  for (int i = 0; i < 3; ++i) g.center[i] = o.center[i];
  static_cast<std::vector<golden::GoldenObject>*>(context)->push_back(g);
}

// A lost window outranks anything else.
Status worse(Status a, Status b) {
  if (a == Status::kWindowOverflow || b == Status::kWindowOverflow) return Status::kWindowOverflow;
  return a != Status::kOk ? a : b;
}

}  // namespace

GoldenStreamRun run_golden_stream(const Database& db, const std::vector<double>& xyz, size_t chunk) {
  GoldenStreamRun run;
  const StreamConfig config = golden::golden_stream_config();
  host::AlignedBytes workspace(required_stream_workspace_bytes(config));
  SceneStream stream;
  run.status = stream.init(&db, config, workspace.data(), workspace.size(), keep, &run.objects);
  if (run.status != Status::kOk) return run;
  const size_t n = xyz.size() / 3;
  for (size_t i = 0; i < n; i += chunk) {
    const auto m = static_cast<uint32_t>(std::min(chunk, n - i));
    run.status = worse(run.status, stream.push(xyz.data() + 3 * i, m));
  }
  run.status = worse(run.status, stream.flush());
  const StreamStats& s = stream.stats();
  run.stats = golden::GoldenStreamStats{s.points_pushed, s.windows, s.objects_reported, s.objects_not_owned};
  return run;
}

}  // namespace test
}  // namespace spinhash
