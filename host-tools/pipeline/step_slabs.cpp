#include "pipeline/step_slabs.hpp"

#include <sys/mman.h>

#include <cstdlib>
#include <new>

namespace spinhash::pipeline {

namespace {

constexpr size_t kHugePage = size_t{2} << 20;

}  // namespace

void StepSlabs::FreeSlab::operator()(int32_t* p) const { std::free(p); }

int32_t* StepSlabs::alloc(size_t ints) {
  if (ints > kSlabInts) throw std::bad_alloc();
  if (slab_ < slabs_.size() && used_ + ints > kSlabInts) {  // this slab's tail is too short
    ++slab_;
    used_ = 0;
  }
  if (slab_ == slabs_.size()) {
    void* p = std::aligned_alloc(kHugePage, kSlabBytes);
    if (p == nullptr) throw std::bad_alloc();
    madvise(p, kSlabBytes, MADV_HUGEPAGE);  // a hint: without huge pages, 4 kB ones
    slabs_.emplace_back(static_cast<int32_t*>(p));
    used_ = 0;
  }
  int32_t* block = slabs_[slab_].get() + used_;
  used_ += ints;
  return block;
}

void StepSlabs::clear() {
  slab_ = 0;
  used_ = 0;
}

}  // namespace spinhash::pipeline
