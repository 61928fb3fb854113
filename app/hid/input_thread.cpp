#include "app/hid/input_thread.h"

#include <cstdio>
#include <utility>

#include "app/hid/profile_file.h"

namespace mtcut::app::hid {
namespace {

std::string hex4(int v) {
  char s[8];
  std::snprintf(s, sizeof s, "%04x", v & 0xffff);
  return s;
}

std::string seconds_text(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", s);
  return text;
}

}  // namespace

std::string permission_hint(const std::string& path) {
  return path + ": permission denied; install the udev rule: sudo cp " + profile_dir() +
         "/70-mtcut-hid.rules /etc/udev/rules.d/ && sudo udevadm control --reload-rules && sudo udevadm trigger"
         ", then replug the device";
}

InputThread::InputThread(Transport& transport, Profile profile, InputDef def)
    : transport_(&transport),
      decoder_(std::move(profile)),
      def_(std::move(def)),
      queue_(def_.queue_capacity),
      buffer_(4096) {}

InputThread::~InputThread() { stop(); }

void InputThread::start() {
  if (thread_.joinable()) return;
  if (!def_.record_path.empty()) {
    recorder_.emplace(def_.record_path);
    recorder_->comment("profile " + decoder_.profile().name);
  }
  epoch_ = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(mutex_);
    stopping_ = false;
    status_.stopped = false;
  }
  thread_ = std::thread([this] { run(); });
}

void InputThread::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

std::vector<Sample> InputThread::take_until(std::chrono::steady_clock::time_point t) {
  return queue_.take_until(std::chrono::duration_cast<std::chrono::microseconds>(t - epoch_).count());
}

std::vector<InputEvent> InputThread::take_events() {
  std::lock_guard lock(mutex_);
  return std::exchange(events_, {});
}

InputStatus InputThread::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

bool InputThread::wait_until(const std::function<bool(const InputStatus&)>& done,
                             std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return done(status_); });
}

std::int64_t InputThread::now_us() const {
  if (def_.clock.now_us) return def_.clock.now_us();
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - epoch_).count();
}

void InputThread::wait_until_us(std::int64_t us) const {
  if (def_.clock.wait_until_us) return def_.clock.wait_until_us(us);
  std::this_thread::sleep_until(epoch_ + std::chrono::microseconds(us));
}

void InputThread::emit(InputEvent::Kind kind, const std::string& message) {
  {
    std::lock_guard lock(mutex_);
    events_.push_back({now_us(), kind, message});
  }
  changed_.notify_all();
}

bool InputThread::pause(double seconds) {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return stopping_; });
  return !stopping_;
}

void InputThread::record(const RawEvent& event) {
  if (!recorder_) return;
  recorder_->write(event);
  if (!recorder_->ok()) {
    emit(InputEvent::Kind::record_failed, recorder_->path() + ": cannot write the HID recording; recording stopped");
    recorder_.reset();
  }
}

void InputThread::run() {
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      if (stopping_) break;
    }
    if (device_) {
      read_once();
    } else if (!connect() && !pause(def_.retry_seconds)) {
      break;
    }
  }
  device_.reset();
  {
    std::lock_guard lock(mutex_);
    status_.connected = false;
    status_.stopped = true;
  }
  changed_.notify_all();
}

bool InputThread::connect() {
  const Profile& profile = decoder_.profile();
  std::string path = def_.device_path;
  std::string label;
  {
    std::lock_guard lock(mutex_);
    ++status_.open_attempts;
  }
  if (path.empty()) {
    for (const DeviceInfo& d : transport_->enumerate())
      if (match_score(profile, d) > 0) {
        path = d.path;
        label = " (" + hex4(d.vendor_id) + ":" + hex4(d.product_id) + " " + d.manufacturer + " " + d.product + ")";
        break;
      }
    if (path.empty()) {
      if (!told_no_device_)
        emit(InputEvent::Kind::no_device, "no HID device matches profile '" + profile.name + "'; looking again every " +
                                              seconds_text(def_.retry_seconds));
      told_no_device_ = true;
      changed_.notify_all();
      return false;
    }
  }
  OpenResult opened = transport_->open(path);
  if (opened.status != OpenStatus::ok) {
    {
      std::lock_guard lock(mutex_);
      ++status_.open_failures;
    }
    if (!told_open_failure_) {
      if (opened.status == OpenStatus::permission_denied)
        emit(InputEvent::Kind::permission_denied, permission_hint(path));
      else
        emit(InputEvent::Kind::open_failed, "cannot open " + path + ": " + opened.message + "; retrying");
    }
    told_open_failure_ = true;
    changed_.notify_all();
    return false;
  }
  device_ = std::move(opened.device);
  told_no_device_ = told_open_failure_ = false;
  if (recorder_) recorder_->comment("connected " + path + label);
  {
    std::lock_guard lock(mutex_);
    status_.connected = true;
    status_.device_path = path;
    ++status_.connects;
  }
  emit(InputEvent::Kind::connected, "connected " + path + label + " with profile '" + profile.name + "'");
  return true;
}

void InputThread::read_once() {
  const int n = device_->read(buffer_, def_.read_timeout_ms);
  if (n < 0) return unplug();
  if (n == 0) return;
  RawEvent event{now_us(), RawEvent::Kind::report,
                 std::vector<std::uint8_t>(buffer_.begin(), buffer_.begin() + n)};
  record(event);
  const std::optional<Sample> sample = decoder_.feed(event);
  if (sample) queue_.push(*sample);
  {
    std::lock_guard lock(mutex_);
    status_.counts = decoder_.counts();
    status_.last_reject = decoder_.last_reject();
    if (sample) ++status_.samples;
  }
  changed_.notify_all();
}

void InputThread::unplug() {
  const std::string why = device_->error();
  device_.reset();
  told_no_device_ = true;  // the unplug message says we are looking for it
  const RawEvent event{now_us(), RawEvent::Kind::unplugged, {}};
  record(event);
  queue_.push(*decoder_.feed(event));  // the blade disengaged, the pose held
  std::string path;
  {
    std::lock_guard lock(mutex_);
    status_.connected = false;
    ++status_.unplugs;
    ++status_.samples;
    path = status_.device_path;
  }
  emit(InputEvent::Kind::unplugged, "HID device " + path + " unplugged" + (why.empty() ? "" : " (" + why + ")") +
                                        ": blade disengaged; reconnecting every " + seconds_text(def_.retry_seconds));
}

}  // namespace mtcut::app::hid
