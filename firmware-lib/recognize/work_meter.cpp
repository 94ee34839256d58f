#include "recognize/work_meter.hpp"

namespace spinhash {

uint64_t query_work(const SearchContext& ctx) { return ctx.work_before + pass_work(ctx.stats, ctx.params); }

}  // namespace spinhash
