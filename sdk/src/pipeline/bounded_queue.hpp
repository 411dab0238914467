// pipeline/bounded_queue.hpp — a thread-safe FIFO with a fixed capacity that
// never grows without bound.
//
// push() on a full queue either drops the OLDEST element (latest wins: the
// newest data always gets in; the drop is counted) or, with wait_for_room,
// blocks until a consumer makes room or the queue is closed. close() wakes
// every waiter: pushes after it are refused, pops drain what is left, then
// report "closed". Capacity 0 accepts nothing (every push is a counted drop).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>

namespace onetip::pipeline {

template <typename T>
class BoundedQueue {
 public:
  explicit BoundedQueue(std::size_t capacity) : capacity_(capacity) {}

  enum class PushResult { queued, queued_after_drop, dropped, closed };

  PushResult push(T value, bool wait_for_room = false) {
    std::unique_lock lock(mutex_);
    if (wait_for_room && capacity_ > 0)
      room_.wait(lock, [&] { return closed_ || items_.size() < capacity_; });
    if (closed_) return PushResult::closed;
    if (capacity_ == 0) {
      ++dropped_;
      return PushResult::dropped;
    }
    PushResult result = PushResult::queued;
    if (items_.size() >= capacity_) {
      items_.pop_front();
      ++dropped_;
      result = PushResult::queued_after_drop;
    }
    items_.push_back(std::move(value));
    lock.unlock();
    ready_.notify_one();
    return result;
  }

  // Non-blocking; false when empty.
  bool tryPop(T& out) {
    std::unique_lock lock(mutex_);
    return popLocked(out, lock);
  }

  // Waits up to `timeout` (negative: no limit) for an element; false on
  // time-out or when the queue is closed and empty.
  template <typename Rep, typename Period>
  bool waitPop(T& out, std::chrono::duration<Rep, Period> timeout) {
    std::unique_lock lock(mutex_);
    const auto has_item = [&] { return closed_ || !items_.empty(); };
    if (timeout < timeout.zero())
      ready_.wait(lock, has_item);
    else
      ready_.wait_for(lock, timeout, has_item);
    return popLocked(out, lock);
  }

  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    ready_.notify_all();
    room_.notify_all();
  }

  bool closed() const {
    std::lock_guard lock(mutex_);
    return closed_;
  }
  std::int64_t dropped() const {
    std::lock_guard lock(mutex_);
    return dropped_;
  }
  std::size_t size() const {
    std::lock_guard lock(mutex_);
    return items_.size();
  }

 private:
  bool popLocked(T& out, std::unique_lock<std::mutex>& lock) {
    if (items_.empty()) return false;
    out = std::move(items_.front());
    items_.pop_front();
    lock.unlock();
    room_.notify_one();
    return true;
  }

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable ready_, room_;
  std::deque<T> items_;
  std::int64_t dropped_ = 0;
  bool closed_ = false;
};

}  // namespace onetip::pipeline
