// Counts heap allocations (malloc, calloc, realloc) made by the calling thread. Linking
// allocation_counter.cpp replaces malloc for the whole test program.
#pragma once

namespace cerebellum::qp::fixtures {

class AllocationCounter {
 public:
  AllocationCounter();   // starts counting
  ~AllocationCounter();  // stops counting
  AllocationCounter(const AllocationCounter&) = delete;
  AllocationCounter& operator=(const AllocationCounter&) = delete;
  long count() const;
};

}  // namespace cerebellum::qp::fixtures
