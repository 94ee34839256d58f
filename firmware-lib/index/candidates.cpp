#include "spinhash/internal/lsh_search.hpp"

#include <cmath>

#include "kernels/l1_select.hpp"
#include "spinhash/limits.hpp"
#include "spinhash/lsh.hpp"
#include "util/fibonacci_hash.hpp"
#include "util/heap_sort.hpp"

namespace spinhash {

namespace {

constexpr uint32_t kNoBound = 0xFFFFFFFFu;  // a list still filling takes any distance

// The order of a top-W list: nearer first, equal distances by feature index.
// One 64-bit comparison: distance in the high word, feature in the low.
inline uint64_t order_key(const Candidate& c) { return static_cast<uint64_t>(c.distance) << 32 | c.feature; }
inline bool before(const Candidate& x, const Candidate& y) { return order_key(x) < order_key(y); }

// The LSH scan keeps its top W as a heap whose root is the farthest kept
// candidate (O(log W) per entering candidate, against O(W) for a sorted
// list), then sorts it once: the same list as insert_top_w.
void sift_down_farthest(Candidate* heap, uint32_t n, uint32_t root) {
  for (uint32_t child = 2u * root + 1u; child < n; child = 2u * root + 1u) {
    if (child + 1u < n && before(heap[child], heap[child + 1u])) ++child;
    if (!before(heap[root], heap[child])) return;
    const Candidate tmp = heap[root];
    heap[root] = heap[child];
    heap[child] = tmp;
    root = child;
  }
}

void push_farthest_first(Candidate* heap, uint32_t* count, const Candidate& c) {
  uint32_t i = (*count)++;
  heap[i] = c;
  while (i > 0 && before(heap[(i - 1u) / 2u], heap[i])) {
    const uint32_t parent = (i - 1u) / 2u;
    heap[i] = heap[parent];
    heap[parent] = c;
    i = parent;
  }
}

// Whether c enters a full or filling heap of at most w candidates.
inline bool enters_heap(const Candidate* heap, uint32_t count, uint32_t w, const Candidate& c) {
  return count < w || before(c, heap[0]);
}

void keep_in_heap(Candidate* heap, uint32_t* count, uint32_t w, const Candidate& c) {
  if (*count < w) {
    push_farthest_first(heap, count, c);
    return;
  }
  heap[0] = c;  // replaces the farthest
  sift_down_farthest(heap, w, 0u);
}

}  // namespace

void insert_top_w(Candidate* list, uint32_t* count, uint32_t w, Candidate c) {
  uint32_t n = *count;
  if (n == w && !before(c, list[n - 1u])) return;
  uint32_t i = n < w ? n : w - 1u;  // slot freed at the end
  while (i > 0 && before(c, list[i - 1u])) {
    list[i] = list[i - 1u];
    --i;
  }
  list[i] = c;
  if (n < w) *count = n + 1u;
}

bool LshSearcher::carve(Arena& arena, uint32_t max_scan) {
  max_scan_ = scan_ = max_scan;
  capacity_ = next_pow2(2u * (max_scan > 0 ? max_scan : 1u));
  slot_shift_ = slot_shift(capacity_);
  seen_ = arena.alloc<uint32_t>(capacity_);
  stamp_ = arena.alloc<uint32_t>(capacity_);
  if (stamp_ != nullptr)
    for (uint32_t i = 0; i < capacity_; ++i) stamp_[i] = 0;
  generation_ = 0;
  return !arena.overflowed();
}

void LshSearcher::set_scan(uint32_t scan) { scan_ = scan < max_scan_ ? scan : max_scan_; }

bool LshSearcher::mark_seen(uint32_t feature) {
  uint32_t slot = slot_of(feature * kFibonacciMultiplier, slot_shift_);
  // At most max_scan insertions per generation: load <= 1/2, a free slot exists.
  for (uint32_t probe = 0; probe < capacity_; ++probe) {
    if (stamp_[slot] != generation_) {
      stamp_[slot] = generation_;
      seen_[slot] = feature;
      return true;
    }
    if (seen_[slot] == feature) return false;
    slot = (slot + 1u) & (capacity_ - 1u);
  }
  return false;
}

uint32_t LshSearcher::search(const Database& db, const uint8_t* spin, uint32_t w, Candidate* out,
                             SearchStats* stats) {
  if (++generation_ == 0) {  // wrapped: stale stamps could alias, so clear once
    for (uint32_t i = 0; i < capacity_; ++i) stamp_[i] = 0;
    generation_ = 1;
  }
  const blob::Params& p = db.params();
  const uint32_t dims = db.spin_dims();
  const uint8_t* spins = db.spin(0);
  // Every table gets an equal share of the scan bound; a bucket larger than
  // its share (a very common descriptor, e.g. a flat patch) is sampled with
  // a fixed stride, so one crowded table cannot starve the others.
  const uint32_t share = scan_ / p.lsh_tables > 0 ? scan_ / p.lsh_tables : 1u;
  uint32_t count = 0;
  // One bucket entry: its distance stops at the first block past the
  // farthest kept candidate (l1_distance_within), and most entries are
  // dropped there, before the seen-set (the list only gets nearer, so a
  // repeat is dropped again; a repeat that would enter is already in it).
  uint32_t bound = kNoBound;  // the farthest kept distance once the list is full
  auto consider = [&](uint32_t f) {
    const uint32_t d = kernels::l1_distance_within(spin, spins + static_cast<size_t>(f) * dims, dims, bound);
    if (d > bound) return;  // farther than the farthest of a full list (a filling one takes any)
    const Candidate c{f, d};
    if (!enters_heap(out, count, w, c) || !mark_seen(f)) return;
    keep_in_heap(out, &count, w, c);
    if (count == w) bound = out[0].distance;
  };
  // The L buckets, smallest first: the top-W list holds the W nearest
  // distinct features whatever the order they come in (a total order,
  // distance then index), and a small bucket's specific features fill it
  // with near ones early, so that more of the large buckets' entries stop
  // at the bound.
  uint32_t firsts[kMaxLshTables], sizes[kMaxLshTables], tables[kMaxLshTables];
  for (uint32_t t = 0; t < p.lsh_tables; ++t) {
    const uint32_t bucket = blob::bucket_of(lsh_key(db.lsh_bits(t), p.lsh_bits, spin), t, p.lsh_buckets);
    const uint32_t* offsets = db.lsh_offsets(t);
    const uint32_t first = offsets[bucket], size = offsets[bucket + 1u] - first;
    uint32_t i = t;
    for (; i > 0 && sizes[i - 1u] > size; --i) {
      firsts[i] = firsts[i - 1u];
      sizes[i] = sizes[i - 1u];
      tables[i] = tables[i - 1u];
    }
    firsts[i] = first;
    sizes[i] = size;
    tables[i] = t;
  }
  for (uint32_t k = 0; k < p.lsh_tables; ++k) {
    const uint32_t first = firsts[k], size = sizes[k];
    const uint32_t* entries = db.lsh_entries() + static_cast<size_t>(tables[k]) * p.feature_count + first;
    const uint32_t take = size < share ? size : share;
    stats->truncated = stats->truncated || take < size;
    stats->entries_scanned += take;
    if (w == 0) continue;             // nothing can enter: no distance is needed
    const bool whole = take == size;  // the whole bucket, in order: no stride to work out
    for (uint32_t e = 0; e < take; ++e)
      consider(entries[whole ? e : static_cast<uint32_t>(static_cast<uint64_t>(e) * size / take)]);
  }
  // A lambda, not the function: the sort then inlines the comparison.
  heap_sort(out, count, [](const Candidate& x, const Candidate& y) { return before(x, y); });
  return count;
}

uint32_t search_model_exhaustive(const Database& db, uint32_t model, const uint8_t* spin, uint32_t w,
                                 Candidate* out) {
  const blob::ModelRecord& rec = db.model(model);
  const uint32_t dims = db.spin_dims();
  uint32_t count = 0;
  for (uint32_t f = rec.first_feature; f < rec.first_feature + rec.feature_count; ++f) {
    // A feature farther than the farthest of a full list cannot enter it:
    // its distance stops at the first block past that bound (same list).
    const bool full = w > 0 && count == w;
    const uint32_t bound = full ? out[w - 1u].distance : kNoBound;
    const uint32_t d = kernels::l1_distance_within(spin, db.spin(f), dims, bound);
    if (full && d > bound) continue;  // most features: no call
    insert_top_w(out, &count, w, Candidate{f, d});
  }
  return count;
}

float candidate_entropy(const Database& db, const Candidate* list, uint32_t n) {
  if (n == 0) return 0.0f;
  if (n > kMaxCandidates) n = kMaxCandidates;
  // The distinct models and their counts (a list names few models: a
  // linear scan of the distinct ones is cheaper than sorting all n ids).
  uint16_t models[kMaxCandidates];
  uint32_t counts[kMaxCandidates];
  uint32_t distinct = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const uint16_t m = db.feature_models()[list[i].feature];
    uint32_t j = 0;
    while (j < distinct && models[j] != m) ++j;
    if (j == distinct) {
      models[distinct] = m;
      counts[distinct++] = 0;
    }
    ++counts[j];
  }
  // Summed in ascending model order: the same float sum on every target.
  for (uint32_t i = 1; i < distinct; ++i) {
    const uint16_t m = models[i];
    const uint32_t c = counts[i];
    uint32_t j = i;
    for (; j > 0 && models[j - 1u] > m; --j) {
      models[j] = models[j - 1u];
      counts[j] = counts[j - 1u];
    }
    models[j] = m;
    counts[j] = c;
  }
  float entropy = 0.0f;
  for (uint32_t i = 0; i < distinct; ++i) {
    float pr = static_cast<float>(counts[i]) / static_cast<float>(n);
    entropy -= pr * std::log(pr);
  }
  return entropy;
}

}  // namespace spinhash
