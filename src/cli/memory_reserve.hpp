// Out of memory is an answer (exit 4, "undecided: out of memory"), never an abort.
// nlohmann::json allocates while it destroys an array or an object (json_value::destroy moves
// the tree into a vector first, to avoid deep recursion), in a destructor that may not throw: a
// bad_alloc thrown there, while the unwinding of the first bad_alloc frees a document, calls
// std::terminate. So while a command line runs, a reserve of address space is held, and the first
// allocation that fails releases it before bad_alloc is thrown: the unwinding and the error
// document then have memory.
#pragma once
#include <new>

namespace superpack::cli {

// Holds the reserve and installs the new-handler that releases it; the destructor restores the
// previous handler (the Python module runs command lines in its own process) and releases what
// is left. One at a time.
class MemoryReserve {
  public:
    MemoryReserve();
    ~MemoryReserve();
    MemoryReserve(const MemoryReserve&) = delete;
    MemoryReserve& operator=(const MemoryReserve&) = delete;

  private:
    std::new_handler previous_;
};

}  // namespace superpack::cli
