#include "memory_reserve.hpp"

#include <sys/mman.h>

#include <atomic>

namespace superpack::cli {

namespace {

// Address space only (no access, so no memory is committed), counted by ulimit -v as the
// allocations are. nlohmann's destroy needs 16 bytes per element of the largest array or object
// being freed: 64 MiB covers four million.
constexpr std::size_t reserve_bytes = std::size_t(64) << 20;

std::atomic<void*> reserve{nullptr};

void release_reserve() {
    void* block = reserve.exchange(nullptr);
    if (block != nullptr) munmap(block, reserve_bytes);
}

// Called by operator new when an allocation fails (in any thread). It never lets the allocation
// retry into the reserve: the computation stops at the first failure, and the freed space is
// the unwinding's.
void out_of_memory() {
    release_reserve();
    throw std::bad_alloc();
}

}  // namespace

MemoryReserve::MemoryReserve() {
    void* block = mmap(nullptr, reserve_bytes, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    reserve.store(block == MAP_FAILED ? nullptr : block);
    previous_ = std::set_new_handler(out_of_memory);
}

MemoryReserve::~MemoryReserve() {
    std::set_new_handler(previous_);
    release_reserve();
}

}  // namespace superpack::cli
