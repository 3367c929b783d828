#pragma once
// Measures how long the UI event loop goes without ticking: a 50 ms timer
// records the longest gap between its ticks (a frozen window shows as a gap
// of the freeze's length). `onTick` runs at every tick, e.g. to look at the
// busy indicator while the work runs.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <algorithm>
#include <functional>

namespace auv::testing {

class EventLoopGapMeter {
 public:
  explicit EventLoopGapMeter(std::function<void()> on_tick = {}) : on_tick_(std::move(on_tick)) {
    timer_.setInterval(50);
    QObject::connect(&timer_, &QTimer::timeout, [this] {
      const double ms = static_cast<double>(since_.nsecsElapsed()) * 1e-6;
      worst_ms_ = std::max(worst_ms_, ms);
      since_.restart();
      ++ticks_;
      if (on_tick_) on_tick_();
    });
    since_.start();
    timer_.start();
  }
  double worstGapMs() const { return worst_ms_; }
  int ticks() const { return ticks_; }

 private:
  std::function<void()> on_tick_;
  QTimer timer_;
  QElapsedTimer since_;
  double worst_ms_ = 0.0;
  int ticks_ = 0;
};

}  // namespace auv::testing
