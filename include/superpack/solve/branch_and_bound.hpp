// The one branch-and-bound engine of superpack: a work queue of boxes (of any kind and
// dimension) that a driver examines one at a time. The driver says only "this box is a leaf"
// (decided, or given up, with its reason) or "split this box" (after whatever contraction it
// proved), and how a box splits (Examined below also lets it defer a box or stop the run). The
// engine keeps the queue (depth first or best first), runs it on N threads, spends a box budget,
// takes a shard of the start boxes, reports progress, counts the leaves by their reason and, on
// request, records each start box's proof tree.
//
// What a run proves is the driver's: the engine drops no box. Every box it takes from the queue
// ends as a leaf the driver made (examine or unexamined), is split into children that are
// queued, or is queued again (deferred); when the run stops early (the budget is spent, or the
// driver stops at a box), every box still queued is handed to the driver's `unexamined` and so
// also ends as a leaf. Only a leaf that answers the whole run (a witness) drops the boxes still
// queued. An exception thrown by the driver ends the run the same way on any number of threads
// and is rethrown to the caller once every thread is done.
//
// The driver (a class; with threads > 1, examine, split and priority must be safe to call
// concurrently, collect is called under the engine's lock):
//   using Box = ...; using Leaf = ...;
//   Examined<Box, Leaf> examine(const Box& box, Visit& visit);  the box's leaf, or what to do with it
//   std::array<Box, 2> split(const Box& box);                    its two children, in the order to visit
//   void collect(Leaf&& leaf);                                   every leaf, in the order they close
// and, where needed:
//   Leaf unexamined(const Box& box);     a box left when the run stopped early (a run with a box
//                                        budget is refused without it, and a stop fails)
//   std::size_t reason(const Leaf& leaf);  the leaf's reason, an index from 0; a driver whose
//                                        leaves have one reason says so instead, with
//                                        `static constexpr bool single_reason = true;` (all count
//                                        as 0), so that a misspelt reason does not compile
//   double priority(const Box& box);     best first only: the least is taken first
// With one thread the run is deterministic: depth first visits each box's first child (and its
// whole subtree) before its second, and best first breaks ties as std::priority_queue does.
#pragma once
#include <algorithm>
#include <array>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <queue>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace superpack {

enum class BranchOrder {
    depth_first,  // a stack: short, and a 1-D domain's leaves close from left to right
    best_first,   // the least priority first (a global minimisation's order)
};

// A snapshot of a run, for progress lines.
struct BranchProgress {
    long processed = 0;  // boxes taken from the queue (examined, or leaves unexamined)
    long queued = 0;
    std::vector<long> counts;  // leaves by reason
    double seconds = 0;
};

struct BranchOptions {
    BranchOrder order = BranchOrder::depth_first;
    int threads = 1;  // 1: the run happens in the calling thread
    long max_boxes = std::numeric_limits<long>::max();  // boxes examined; later ones are left unexamined
    int shard = 0, shards = 1;  // the start boxes whose index is shard mod shards
    // Record each start box's tree: the letters examine writes for each box, in pre-order.
    bool record_trees = false;
    std::function<void(const BranchProgress&)> progress;  // from a monitor thread, every progress_interval
    std::chrono::milliseconds progress_interval{2000};
};

// What the driver says about one box:
//   leaf     the box ends as this leaf; with `stop` the leaf answers the whole run (a witness):
//            the run ends and the boxes still queued are dropped, since nothing they hold can
//            change the answer;
//   split    the box (possibly contracted) is split, and its children are queued;
//   defer    the box goes back into the queue in best-first order under `priority`, after every
//            box queued depth first: a driver that examines new boxes at once (depth first) and
//            then takes them by priority (a global minimisation) defers the ones it has bounded;
//   stop     the run ends before this box: it and every box still queued are left unexamined
//            (handed to `unexamined`, this one first), as when the budget is spent.
template <class Box, class Leaf>
struct Examined {
    enum class Action { leaf, split, defer, stop };
    Action action = Action::leaf;
    std::optional<Leaf> leaf;
    std::optional<Box> box;  // to split, defer or leave (a box need not have a default value)
    double priority = 0;
    bool stop = false;
};
// The four answers, one each.
template <class Box, class Leaf>
Examined<Box, Leaf> leaf_of(Leaf leaf, bool stop = false) {
    return {Examined<Box, Leaf>::Action::leaf, std::move(leaf), std::nullopt, 0, stop};
}
template <class Box, class Leaf>
Examined<Box, Leaf> split_of(Box box) {
    return {Examined<Box, Leaf>::Action::split, std::nullopt, std::move(box)};
}
template <class Box, class Leaf>
Examined<Box, Leaf> defer_of(Box box, double priority) {
    return {Examined<Box, Leaf>::Action::defer, std::nullopt, std::move(box), priority};
}
template <class Box, class Leaf>
Examined<Box, Leaf> stop_at(Box box) {
    return {Examined<Box, Leaf>::Action::stop, std::nullopt, std::move(box)};
}

// What examine may read and write besides the box: the run's size when the box was taken (so
// that a driver can give up on a box when leaves and queue together would pass its own limit;
// exact with one thread), and, when trees are recorded, the box's letters.
struct Visit {
    long closed_leaves = 0;
    long queued = 0;    // all boxes queued (the one examined is not among them)
    long deferred = 0;  // of which in best-first order
    std::string* letters = nullptr;
};

template <class Box>
struct BranchResult {
    std::vector<long> counts;  // leaves by reason
    long processed = 0;        // boxes taken from the queue
    long examined = 0;         // of which handed to examine (the others were left unexamined)
    bool stopped = false;      // a leaf answered the run, the driver stopped at a box, or an error
    std::vector<Box> starts;   // this shard's start boxes, in order
    std::vector<std::string> trees;  // with record_trees: each start box's tree, in the same order
};

// The start boxes of a run split `depth` times each by `split`, in order: start box by start
// box, each one's first child's boxes before its second's.
template <class Box, class Split>
std::vector<Box> split_start_boxes(std::vector<Box> boxes, int depth, const Split& split) {
    for (int level = 0; level < depth; ++level) {
        std::vector<Box> children;
        for (const Box& box : boxes)
            for (Box& child : split(box)) children.push_back(std::move(child));
        boxes.swap(children);
    }
    return boxes;
}

namespace search_detail {

// A box in the queue with its place in its tree (the start box's index in 6 digits, then 0 or
// 1 per split: sorted by place, the recorded letters are the trees in pre-order) and, best
// first, its priority.
template <class Box>
struct Entry {
    Box box;
    std::string place;
    double priority = 0;
    bool operator<(const Entry& other) const { return priority > other.priority; }  // least on top
};

// The open boxes: a stack (depth first) and a heap (best first, and deferred boxes); the stack
// is emptied first.
template <class Box>
class Open {
  public:
    explicit Open(BranchOrder order) : order_(order) {}
    bool empty() const { return stack_.empty() && heap_.empty(); }
    std::size_t size() const { return stack_.size() + heap_.size(); }
    void clear() {
        stack_.clear();
        heap_ = std::priority_queue<Entry<Box>>();
    }
    std::size_t deferred() const { return heap_.size(); }
    void defer(Entry<Box>&& entry) { heap_.push(std::move(entry)); }
    Entry<Box> pop() {
        if (!stack_.empty()) {
            Entry<Box> entry = std::move(stack_.back());
            stack_.pop_back();
            return entry;
        }
        // Moved, not copied: a copy may allocate, and a worker takes it outside its try.
        Entry<Box> entry = std::move(const_cast<Entry<Box>&>(heap_.top()));
        heap_.pop();
        return entry;
    }
    // In the search's order; depth first, pushed last first so that the first is visited first.
    template <class Entries>
    void push(Entries&& entries) {
        if (order_ == BranchOrder::best_first) {
            for (auto& entry : entries) heap_.push(std::move(entry));
            return;
        }
        for (auto entry = entries.rbegin(); entry != entries.rend(); ++entry) stack_.push_back(std::move(*entry));
    }

  private:
    BranchOrder order_;
    std::vector<Entry<Box>> stack_;
    std::priority_queue<Entry<Box>> heap_;
};

// Does the driver give priorities (needed for best first only)?
template <class Driver, class = void>
struct has_priority : std::false_type {};
template <class Driver>
struct has_priority<Driver, std::void_t<decltype(std::declval<Driver&>().priority(std::declval<const typename Driver::Box&>()))>>
    : std::true_type {};

// Does the driver make leaves of unexamined boxes, and does it give its leaves reasons?
template <class Driver, class = void>
struct has_unexamined : std::false_type {};
template <class Driver>
struct has_unexamined<Driver, std::void_t<decltype(std::declval<Driver&>().unexamined(std::declval<const typename Driver::Box&>()))>>
    : std::true_type {};
template <class Driver, class = void>
struct has_reason : std::false_type {};
template <class Driver>
struct has_reason<Driver, std::void_t<decltype(std::declval<Driver&>().reason(std::declval<const typename Driver::Leaf&>()))>>
    : std::true_type {};
template <class Driver, class = void>
struct has_single_reason : std::false_type {};
template <class Driver>
struct has_single_reason<Driver, std::void_t<decltype(Driver::single_reason)>> : std::bool_constant<Driver::single_reason> {};

std::string tree_place(std::size_t index);
std::vector<std::string> assemble_trees(std::vector<std::pair<std::string, std::string>>& records, std::size_t count);

template <class Driver>
class Search {
  public:
    using Box = typename Driver::Box;
    using Leaf = typename Driver::Leaf;

    Search(Driver& driver, const BranchOptions& options) : driver_(driver), options_(options), open_(options.order) {}

    static_assert(has_reason<Driver>::value != has_single_reason<Driver>::value,
                  "branch and bound: a driver gives its leaves' reasons or declares single_reason, not both");

    BranchResult<Box> run(const std::vector<Box>& start) {
        if (options_.order == BranchOrder::best_first && !has_priority<Driver>::value)
            throw std::logic_error("branch and bound: best first needs the driver's priority");
        if (!has_unexamined<Driver>::value && options_.max_boxes != std::numeric_limits<long>::max())
            throw std::logic_error("branch and bound: a box budget needs the driver's unexamined");
        BranchResult<Box> result;
        const std::size_t shards = static_cast<std::size_t>(std::max(1, options_.shards));
        for (std::size_t k = 0; k < start.size(); ++k)
            if (k % shards == static_cast<std::size_t>(options_.shard)) result.starts.push_back(start[k]);
        std::vector<Entry<Box>> entries;
        for (std::size_t k = 0; k < result.starts.size(); ++k) entries.push_back(start_entry(result.starts[k], k));
        open_.push(entries);
        begin_ = std::chrono::steady_clock::now();
        std::thread monitor;
        if (options_.progress) monitor = std::thread([&] { report_progress(); });
        if (options_.threads <= 1)
            work();
        else
            run_workers();
        {
            // No worker may have started (run_workers failed at once) to say so.
            const std::lock_guard<std::mutex> lock(mutex_);
            finished_ = true;
        }
        wake_.notify_all();
        if (monitor.joinable()) monitor.join();
        if (error_) std::rethrow_exception(error_);
        result.counts = std::move(counts_);  // (a copy-assignment here trips g++ 12's -Wnonnull)
        result.processed = processed_;
        result.examined = examined_;
        result.stopped = stopped_;
        if (options_.record_trees) result.trees = assemble_trees(records_, result.starts.size());
        return result;
    }

  private:
    // The worker threads, joined. A thread that cannot start (out of memory or of threads) fails
    // the run like an error of a box, and those started finish: a joinable std::thread destroyed
    // would abort the process.
    void run_workers() {
        std::vector<std::thread> threads;
        try {
            for (int t = 0; t < options_.threads; ++t) threads.emplace_back([&] { work(); });
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mutex_);
            abandon(std::current_exception());
        }
        for (std::thread& thread : threads) thread.join();
    }

    Entry<Box> start_entry(const Box& box, std::size_t index) {
        Entry<Box> entry{box, options_.record_trees ? tree_place(index) : std::string(), 0};
        entry.priority = priority(entry.box);
        return entry;
    }

    // Depth first, a box queued by a split needs none.
    double priority(const Box& box) {
        if constexpr (has_priority<Driver>::value) {
            if (options_.order == BranchOrder::best_first) return driver_.priority(box);
        }
        return 0;
    }

    void work() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return !open_.empty() || active_ == 0; });
            if (open_.empty()) {
                finished_ = true;
                wake_.notify_all();
                return;
            }
            Entry<Box> taken = open_.pop();
            const bool to_examine = !stopped_ && processed_ < options_.max_boxes;
            ++processed_;
            if (to_examine) ++examined_;
            ++active_;
            std::string letters;
            Visit visit{static_cast<long>(closed_), static_cast<long>(open_.size()), static_cast<long>(open_.deferred()),
                        options_.record_trees ? &letters : nullptr};
            lock.unlock();
            std::optional<Examined<Box, Leaf>> examined;
            std::vector<Entry<Box>> children;
            try {
                examined = decide(taken, to_examine, visit, children);
            } catch (...) {
                lock.lock();
                fail(std::current_exception());
                continue;
            }
            lock.lock();
            try {
                if (options_.record_trees) records_.emplace_back(taken.place, std::move(letters));
                settle(taken, *examined, children);
            } catch (...) {
                fail(std::current_exception());
                continue;
            }
            --active_;
            wake_.notify_all();
        }
    }

    Leaf unexamined(const Box& box) {
        if constexpr (has_unexamined<Driver>::value) {
            return driver_.unexamined(box);
        } else {
            throw std::logic_error("branch and bound: a box was left unexamined, and the driver makes no leaf of it");
        }
    }

    // What becomes of a box taken from the queue, outside the lock: the driver's answer and, for
    // a split, the children with their places and priorities.
    Examined<Box, Leaf> decide(const Entry<Box>& taken, bool to_examine, Visit& visit, std::vector<Entry<Box>>& children) {
        using Action = typename Examined<Box, Leaf>::Action;
        Examined<Box, Leaf> examined = to_examine ? driver_.examine(taken.box, visit) : leaf_of<Box>(unexamined(taken.box));
        if (examined.action == Action::stop) examined.leaf = unexamined(*examined.box);
        if (examined.action == Action::defer && options_.record_trees)
            throw std::logic_error("branch and bound: a deferred box has no place in a recorded tree");
        if (examined.action == Action::split) {
            std::array<Box, 2> halves = driver_.split(*examined.box);
            for (int half = 0; half < 2; ++half) {
                children.push_back({std::move(halves[half]), taken.place.empty() ? std::string() : taken.place + char('0' + half), 0});
                children.back().priority = priority(children.back().box);
            }
        }
        return examined;
    }

    // Under the lock: the children queued, the box deferred, or the leaf counted and collected.
    // Once the run is answered (a leaf of another thread) or failed, the box is dropped.
    void settle(Entry<Box>& taken, Examined<Box, Leaf>& examined, std::vector<Entry<Box>>& children) {
        using Action = typename Examined<Box, Leaf>::Action;
        if (answered_ || error_) return;
        if (examined.action == Action::split) {
            open_.push(children);
            return;
        }
        if (examined.action == Action::defer) {
            open_.defer({std::move(*examined.box), std::move(taken.place), examined.priority});
            return;
        }
        std::size_t reason = 0;
        if constexpr (has_reason<Driver>::value) reason = driver_.reason(*examined.leaf);
        if (reason >= counts_.size()) counts_.resize(reason + 1, 0);
        ++counts_[reason];
        ++closed_;
        if (examined.stop || examined.action == Action::stop) stopped_ = true;
        if (examined.stop) {
            answered_ = true;
            open_.clear();
        }
        driver_.collect(std::move(*examined.leaf));
    }

    // Under the lock: the run ends, and the first error is rethrown by run() once every thread
    // is done.
    void fail(std::exception_ptr error) {
        --active_;
        abandon(error);
    }

    // Under the lock: the run stops with `error` (the first one is kept), by a thread that holds
    // no box.
    void abandon(std::exception_ptr error) {
        if (!error_) error_ = error;
        stopped_ = true;
        open_.clear();
        wake_.notify_all();
    }

    // An exception may not leave a thread (std::terminate): a report that fails (out of memory)
    // fails the run.
    void report_progress() {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!wake_.wait_for(lock, options_.progress_interval, [&] { return finished_; })) {
            try {
                const BranchProgress progress{processed_, static_cast<long>(open_.size()), counts_,
                                              std::chrono::duration<double>(std::chrono::steady_clock::now() - begin_).count()};
                lock.unlock();
                options_.progress(progress);
                lock.lock();
            } catch (...) {
                if (!lock.owns_lock()) lock.lock();
                abandon(std::current_exception());
                return;
            }
        }
    }

    Driver& driver_;
    const BranchOptions& options_;
    std::mutex mutex_;
    std::condition_variable wake_;
    Open<Box> open_;
    std::vector<std::pair<std::string, std::string>> records_;
    std::vector<long> counts_;
    long processed_ = 0, examined_ = 0;
    std::size_t closed_ = 0;
    int active_ = 0;
    bool stopped_ = false, answered_ = false, finished_ = false;
    std::exception_ptr error_;
    std::chrono::steady_clock::time_point begin_;
};

}  // namespace search_detail

// Runs the driver over this shard of `start` (see the top of this file).
template <class Driver>
BranchResult<typename Driver::Box> branch_and_bound(Driver& driver, const std::vector<typename Driver::Box>& start,
                                                    const BranchOptions& options) {
    return search_detail::Search<Driver>(driver, options).run(start);
}

}  // namespace superpack
