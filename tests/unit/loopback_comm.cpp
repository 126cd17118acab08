#include "loopback_comm.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "solver/parallel/vote_order.hpp"

namespace radx::test {

namespace {

using solver::parallel::Buffer;
using solver::parallel::Comm;
using solver::parallel::Vote;

// What a rank calls, to check that all ranks call the same collective.
struct Call {
  std::string name;
  int root = -1;
  bool operator==(const Call&) const = default;
};

// Raised on a rank released because another rank failed.
struct Released : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The meeting point of the P ranks. All fields are guarded by `mutex`.
class Hub {
 public:
  explicit Hub(int ranks)
      : ranks_(ranks), posted_(static_cast<std::size_t>(ranks)), calls_(static_cast<std::size_t>(ranks)) {}

  // Posts `to_rank` (one message per destination) for collective `call`, waits for every rank, and returns
  // what each rank posted to `rank`, indexed by source.
  std::vector<Buffer> meet(int rank, const Call& call, std::vector<Buffer> to_rank) {
    std::unique_lock lock(mutex_);
    const auto me = static_cast<std::size_t>(rank);
    // Wait until the previous collective has been read by every rank (its posts cleared).
    cv_.wait(lock, [&] { return failed_ || !reading_; });
    throw_if_failed();
    posted_[me] = std::move(to_rank);
    calls_[me] = call;
    const std::uint64_t round = round_;
    if (++arrived_ == ranks_) {
      reading_ = true;
      ++round_;
      cv_.notify_all();
    } else {
      cv_.wait(lock, [&] { return failed_ || round_ != round; });
    }
    throw_if_failed();
    check_same_call();
    std::vector<Buffer> received(static_cast<std::size_t>(ranks_));
    for (std::size_t src = 0; src < received.size(); ++src) received[src] = posted_[src][me];
    if (++departed_ == ranks_) {
      arrived_ = 0;
      departed_ = 0;
      reading_ = false;
      for (auto& p : posted_) p.clear();
      cv_.notify_all();
    }
    return received;
  }

  // A rank failed: every rank waiting now, or arriving later, throws.
  void fail(int rank, const std::string& why) {
    const std::lock_guard lock(mutex_);
    if (!failed_) failure_ = "rank " + std::to_string(rank) + " " + why;
    failed_ = true;
    cv_.notify_all();
  }

  [[nodiscard]] int ranks() const { return ranks_; }

 private:
  void throw_if_failed() const {
    if (failed_) throw Released("loopback rank released: " + failure_);
  }

  // Called with the lock held, once every rank has posted. The first rank to find the calls differ fails
  // the round for all (the others then throw Released with the same text).
  void check_same_call() {
    if (std::all_of(calls_.begin(), calls_.end(), [&](const Call& c) { return c == calls_.front(); })) return;
    std::string why;
    for (std::size_t r = 0; r < calls_.size(); ++r)
      why += (r == 0 ? "rank " : ", rank ") + std::to_string(r) + " called " + describe(calls_[r]);
    failure_ = why;
    failed_ = true;
    cv_.notify_all();
    throw std::logic_error("loopback collectives out of step: " + why);
  }

  static std::string describe(const Call& c) {
    return c.root < 0 ? c.name : c.name + " (root " + std::to_string(c.root) + ")";
  }

  const int ranks_;
  std::mutex mutex_;
  std::condition_variable cv_;
  std::vector<std::vector<Buffer>> posted_;  // [source][destination]
  std::vector<Call> calls_;
  int arrived_ = 0;
  int departed_ = 0;
  bool reading_ = false;  // every rank has posted; some have not yet copied what was posted to them
  std::uint64_t round_ = 0;
  bool failed_ = false;
  std::string failure_;
};

template <class T>
Buffer bytes_of(std::span<const T> values) {
  Buffer b(values.size_bytes());
  if (!values.empty()) std::memcpy(b.data(), values.data(), values.size_bytes());
  return b;
}

template <class T>
std::vector<T> values_of(const Buffer& b) {
  std::vector<T> v(b.size() / sizeof(T));
  if (!v.empty()) std::memcpy(v.data(), b.data(), v.size() * sizeof(T));
  return v;
}

class LoopbackComm final : public Comm {
 public:
  LoopbackComm(Hub& hub, int rank) : hub_(hub), rank_(rank) {}

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return hub_.ranks(); }

  [[nodiscard]] Vote vote(const Vote& mine) override {
    const Vote entry = solver::parallel::vote_of_rank(mine, rank_);
    const auto all = to_all({"vote"}, bytes_of(std::span<const Vote>(&entry, 1)));
    Vote result = values_of<Vote>(all[0]).at(0);
    for (std::size_t r = 1; r < all.size(); ++r)
      result = solver::parallel::combine_votes(result, values_of<Vote>(all[r]).at(0));
    return result;
  }

  void max(std::span<double> values) override {
    const auto all = to_all({"max"}, bytes_of(std::span<const double>(values)));
    for (const auto& b : all) {
      const auto v = values_of<double>(b);
      check_length(v.size(), values.size(), "max");
      for (std::size_t i = 0; i < v.size(); ++i) values[i] = std::max(values[i], v[i]);
    }
  }

  void sum_exact(std::span<std::int64_t> bins) override {
    const auto all = to_all({"sum_exact"}, bytes_of(std::span<const std::int64_t>(bins)));
    std::vector<std::uint64_t> total(bins.size(), 0);  // unsigned: wraps as MPI's integer sum does, no UB
    for (const auto& b : all) {
      const auto v = values_of<std::int64_t>(b);
      check_length(v.size(), bins.size(), "sum_exact");
      for (std::size_t i = 0; i < v.size(); ++i) total[i] += static_cast<std::uint64_t>(v[i]);
    }
    for (std::size_t i = 0; i < bins.size(); ++i) bins[i] = static_cast<std::int64_t>(total[i]);
  }

  void bit_or(std::span<std::uint64_t> words) override {
    const auto all = to_all({"bit_or"}, bytes_of(std::span<const std::uint64_t>(words)));
    for (const auto& b : all) {
      const auto v = values_of<std::uint64_t>(b);
      check_length(v.size(), words.size(), "bit_or");
      for (std::size_t i = 0; i < v.size(); ++i) words[i] |= v[i];
    }
  }

  [[nodiscard]] std::vector<Buffer> exchange(const std::vector<Buffer>& to_rank) override {
    if (to_rank.size() != static_cast<std::size_t>(size()))
      throw std::invalid_argument("LoopbackComm::exchange: " + std::to_string(to_rank.size()) +
                                  " messages for " + std::to_string(size()) + " ranks");
    return hub_.meet(rank_, {"exchange"}, to_rank);
  }

  [[nodiscard]] std::vector<Buffer> gather(const Buffer& mine, int root) override {
    check_root(root, "gather");
    std::vector<Buffer> to_rank(static_cast<std::size_t>(size()));
    to_rank[static_cast<std::size_t>(root)] = mine;
    auto received = hub_.meet(rank_, {"gather", root}, std::move(to_rank));
    if (rank_ != root) return {};
    return received;
  }

  [[nodiscard]] std::vector<Buffer> all_gather(const Buffer& mine) override {
    return to_all({"all_gather"}, mine);
  }

  void broadcast(Buffer& data, int root) override {
    check_root(root, "broadcast");
    std::vector<Buffer> to_rank(static_cast<std::size_t>(size()));
    if (rank_ == root) to_rank.assign(to_rank.size(), data);
    auto received = hub_.meet(rank_, {"broadcast", root}, std::move(to_rank));
    data = std::move(received[static_cast<std::size_t>(root)]);
  }

  void barrier() override { (void)hub_.meet(rank_, {"barrier"}, std::vector<Buffer>(size())); }

  [[noreturn]] void abort(int exit_code, const std::string& message) override {
    hub_.fail(rank_, "aborted (exit code " + std::to_string(exit_code) + "): " + message);
    throw LoopbackAbort(exit_code, message);
  }

 private:
  std::vector<Buffer> to_all(const Call& call, const Buffer& mine) {
    return hub_.meet(rank_, call, std::vector<Buffer>(static_cast<std::size_t>(size()), mine));
  }

  void check_root(int root, const char* what) const {
    if (root < 0 || root >= size())
      throw std::invalid_argument(std::string("LoopbackComm::") + what + ": root " + std::to_string(root) +
                                  " outside 0.." + std::to_string(size() - 1));
  }

  static void check_length(std::size_t theirs, std::size_t mine, const char* what) {
    if (theirs != mine)
      throw std::logic_error(std::string("LoopbackComm::") + what + ": ranks reduce " + std::to_string(mine) +
                             " and " + std::to_string(theirs) + " entries");
  }

  Hub& hub_;
  int rank_;
};

}  // namespace

void run_ranks(int ranks, const std::function<void(Comm&)>& body) {
  if (ranks < 1) throw std::invalid_argument("run_ranks: " + std::to_string(ranks) + " ranks");
  Hub hub(ranks);
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(ranks));
  // One byte per rank, not vector<bool>: threads set their own entries at once, and bits of a word would
  // race.
  std::vector<unsigned char> released(static_cast<std::size_t>(ranks), 0);
  std::vector<std::thread> threads;
  threads.reserve(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) {
    threads.emplace_back([&, r] {
      LoopbackComm comm(hub, r);
      const auto me = static_cast<std::size_t>(r);
      try {
        body(comm);
      } catch (const Released&) {
        errors[me] = std::current_exception();
        released[me] = 1;
      } catch (const std::exception& e) {
        errors[me] = std::current_exception();
        hub.fail(r, std::string("threw: ") + e.what());
      } catch (...) {
        errors[me] = std::current_exception();
        hub.fail(r, "threw");
      }
    });
  }
  for (auto& t : threads) t.join();
  // The failing rank's own exception first; a released rank's only if no rank failed on its own.
  for (std::size_t r = 0; r < errors.size(); ++r)
    if (errors[r] && released[r] == 0) std::rethrow_exception(errors[r]);
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace radx::test
