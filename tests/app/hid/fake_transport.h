#pragma once
// A scripted HID system for tests: the devices enumerate() lists, and reads
// that return recorded bytes, time out, or fail (an unplug). Thread-safe: the
// input thread reads while the test scripts.

#include <condition_variable>
#include <deque>
#include <mutex>

#include "app/hid/transport.h"

namespace mtcut::test {

struct FakeRead {
  enum class Kind { bytes, error };
  Kind kind = Kind::bytes;
  std::vector<std::uint8_t> data;
};

class FakeTransport : public app::hid::Transport {
 public:
  explicit FakeTransport(app::hid::DeviceInfo device) : device_(std::move(device)) {}

  // Reads served in order, by whichever device is open.
  void queue(FakeRead read) {
    std::lock_guard lock(mutex_);
    reads_.push_back(std::move(read));
    more_.notify_all();
  }
  void queue_bytes(std::vector<std::uint8_t> data) { queue({FakeRead::Kind::bytes, std::move(data)}); }
  // The device is gone (a read fails), and absent from the next `absent_for` enumerations.
  void queue_unplug(int absent_for) {
    std::lock_guard lock(mutex_);
    reads_.push_back({FakeRead::Kind::error, {static_cast<std::uint8_t>(absent_for)}});
    more_.notify_all();
  }
  void deny_permission(bool deny) {
    std::lock_guard lock(mutex_);
    deny_ = deny;
  }
  int opens() const {
    std::lock_guard lock(mutex_);
    return opens_;
  }

  std::vector<app::hid::DeviceInfo> enumerate() override {
    std::lock_guard lock(mutex_);
    if (absent_ > 0) {
      --absent_;
      return {};
    }
    return {device_};
  }
  app::hid::OpenResult open(const std::string& path) override;

 private:
  friend class FakeDevice;
  mutable std::mutex mutex_;
  std::condition_variable more_;
  app::hid::DeviceInfo device_;
  std::deque<FakeRead> reads_;
  int absent_ = 0;
  bool deny_ = false;
  int opens_ = 0;
};

class FakeDevice : public app::hid::Device {
 public:
  explicit FakeDevice(FakeTransport& t) : t_(&t) {}
  int read(std::span<std::uint8_t> buffer, int timeout_ms) override {
    std::unique_lock lock(t_->mutex_);
    if (!t_->more_.wait_for(lock, std::chrono::milliseconds(timeout_ms), [&] { return !t_->reads_.empty(); }))
      return 0;
    FakeRead r = std::move(t_->reads_.front());
    t_->reads_.pop_front();
    if (r.kind == FakeRead::Kind::error) {
      t_->absent_ = r.data.at(0);
      return -1;
    }
    std::copy(r.data.begin(), r.data.end(), buffer.begin());
    return static_cast<int>(r.data.size());
  }
  std::string error() const override { return "No such device"; }

 private:
  FakeTransport* t_;
};

inline app::hid::OpenResult FakeTransport::open(const std::string& path) {
  std::lock_guard lock(mutex_);
  ++opens_;
  app::hid::OpenResult result;
  if (path != device_.path) {
    result.message = "no such device";
  } else if (deny_) {
    result.status = app::hid::OpenStatus::permission_denied;
    result.message = "Permission denied";
  } else {
    result.status = app::hid::OpenStatus::ok;
    result.device = std::make_unique<FakeDevice>(*this);
  }
  return result;
}

}  // namespace mtcut::test
