#pragma once
// The HID input thread: opens the profile's device, reads its reports with a
// timeout, timestamps each one on its clock (the steady clock, or the
// caller's: InputClock), decodes it and queues the pose for the frame loop
// (optionally recording the raw reports). Faults
// never reach the caller as exceptions: an unplug is reported once as an
// event, the blade is disengaged (a sample with engaged = false), and the
// device is looked for again every retry interval until it is back.
//
// Use from a frame loop:
//   InputThread hid(transport, load_profile("spacemouse"));
//   hid.start();
//   every frame: for (const Sample& s : hid.take_until(std::chrono::steady_clock::now())) sweep to s.pose;
//                for (const InputEvent& e : hid.take_events()) show e.message;

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/hid/decoder.h"
#include "app/hid/recording.h"
#include "app/hid/sample_queue.h"
#include "app/hid/transport.h"

namespace mtcut::app::hid {

// The input's time, in microseconds since start(): what each report and
// event is stamped with, and what a live feed waits on for its frame's
// samples (HidFeed). Unset: the steady clock, and a wait is a sleep. A test
// moves a clock of its own, so that which frame a sample reaches does not
// depend on how fast the machine runs.
struct InputClock {
  std::function<std::int64_t()> now_us;
  std::function<void(std::int64_t)> wait_until_us;  // returns once now_us() has reached its argument
};

struct InputDef {
  std::string device_path;     // this node; empty: the first device the profile matches, looked up on every (re)connection
  int read_timeout_ms = 50;    // longest block in one read (bounds how long stop() waits)
  double retry_seconds = 1.0;  // between attempts to find or reopen the device
  std::string record_path;     // raw reports recorded here (.hidrec); empty: none
  std::size_t queue_capacity = 65536;
  InputClock clock;            // both functions or neither
};

// Something to tell the user, once per occurrence (console or viewer panel).
struct InputEvent {
  enum class Kind { connected, unplugged, no_device, permission_denied, open_failed, record_failed };
  std::int64_t time_us = 0;  // since epoch()
  Kind kind = Kind::connected;
  std::string message;       // one line
};

struct InputStatus {
  bool connected = false;
  std::string device_path;   // of the open device (or the last one)
  long connects = 0;
  long unplugs = 0;
  long open_attempts = 0;
  long open_failures = 0;    // a device was found but would not open
  long samples = 0;          // queued so far
  DecodeCounts counts;
  std::string last_reject;   // why the last rejected report was rejected
  bool stopped = false;      // the thread has ended
};

class InputThread {
 public:
  // `transport` must outlive the thread.
  InputThread(Transport& transport, Profile profile, InputDef def = {});
  ~InputThread();  // stops
  InputThread(const InputThread&) = delete;
  InputThread& operator=(const InputThread&) = delete;

  // Starts reading; sets epoch(). Throws InputError when the recording cannot be created.
  void start();
  void stop();

  // The steady clock at start(): sample times count from here unless
  // InputDef::clock is given.
  std::chrono::steady_clock::time_point epoch() const { return epoch_; }
  // The profile the reports are decoded with.
  const Profile& profile() const { return decoder_.profile(); }
  // All samples up to `t` not taken yet, oldest first: the frame loop's call.
  std::vector<Sample> take_until(std::chrono::steady_clock::time_point t);
  // The same up to `us` on the input's clock.
  std::vector<Sample> take_until_us(std::int64_t us) { return queue_.take_until(us); }
  // The input's time (InputClock), and a wait until it reaches `us`.
  std::int64_t now_us() const;
  void wait_until_us(std::int64_t us) const;
  std::vector<Sample> take_all() { return queue_.take_all(); }
  std::vector<InputEvent> take_events();
  InputStatus status() const;
  // Waits until `done(status())` holds or `timeout` passes; returns whether it holds.
  bool wait_until(const std::function<bool(const InputStatus&)>& done, std::chrono::milliseconds timeout) const;

 private:
  void run();
  bool connect();
  void read_once();
  void unplug();
  void emit(InputEvent::Kind kind, const std::string& message);
  void record(const RawEvent& event);
  // Waits `seconds` unless stop() comes first; returns false when stopping.
  bool pause(double seconds);

  Transport* transport_;
  Decoder decoder_;  // thread-only after start()
  InputDef def_;
  SampleQueue queue_;
  std::unique_ptr<Device> device_;      // thread-only
  std::optional<Recorder> recorder_;    // thread-only after start()
  std::vector<std::uint8_t> buffer_;    // (4096) one report
  bool told_no_device_ = false;         // "no device" was reported since the last connection
  bool told_open_failure_ = false;      // an open failure was reported since the last connection

  mutable std::mutex mutex_;            // guards what follows
  mutable std::condition_variable changed_;
  InputStatus status_;
  std::vector<InputEvent> events_;
  bool stopping_ = false;

  std::chrono::steady_clock::time_point epoch_;
  std::thread thread_;
};

// The console line telling how to install the udev rule for `path`.
std::string permission_hint(const std::string& path);

}  // namespace mtcut::app::hid
