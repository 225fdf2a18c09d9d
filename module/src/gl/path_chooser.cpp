#include "path_chooser.hpp"

#include <algorithm>
#include <cstdio>

namespace sss::gl {

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

void PathChooser::init(const Functions* gl, bool trustworthy_timer) {
  gl_ = gl;
  timer_ = trustworthy_timer && gl->GetQueryObjectui64v != nullptr;
}

void PathChooser::destroy() {
  if (gl_ == nullptr) return;
  for (Pending& p : pending_) {
    if (p.query != 0) gl_->DeleteQueries(1, &p.query);
  }
  forget();
}

void PathChooser::forget() {
  pending_ = {};
  active_ = -1;
  has_key_ = decided_ = false;
  for (auto& v : samples_) v.clear();
  trials_started_ = 0;
}

void PathChooser::reset(std::uint64_t key) {
  key_ = key;
  has_key_ = true;
  decided_ = false;
  trials_started_ = 0;
  for (auto& v : samples_) {
    v.clear();
    v.reserve(2 * kTrials + 2);  // every pending query's result fits: no allocation after the first reset
  }
  // Results of an earlier configuration's trials still in flight are read and dropped.
  for (Pending& p : pending_) p.waiting = false;
}

void PathChooser::collect() {
  const Functions& f = *gl_;
  for (Pending& p : pending_) {
    if (!p.waiting) continue;
    GLuint available = 0;
    f.GetQueryObjectuiv(p.query, QUERY_RESULT_AVAILABLE, &available);
    if (!available) continue;
    std::uint64_t ns = 0;
    f.GetQueryObjectui64v(p.query, QUERY_RESULT, &ns);
    p.waiting = false;
    samples_[p.compute ? 1 : 0].push_back(static_cast<double>(ns) * 1e-6);
  }
}

PathChooser::Choice PathChooser::choose(std::uint64_t key) {
  decision_[0] = '\0';
  if (!timer_) {
    if (!has_key_ || key != key_) {
      reset(key);
      decided_ = true;
      compute_ = false;
      std::snprintf(decision_.data(), decision_.size(), "%s",
                    "fragment path (no trustworthy timer here; the benchmark measured it faster on software "
                    "rasterisers)");
    }
    return {false, false};
  }
  if (!has_key_ || key != key_) reset(key);
  if (decided_) return {compute_, false};
  collect();
  if (static_cast<int>(samples_[0].size()) >= kTrials && static_cast<int>(samples_[1].size()) >= kTrials) {
    const double fragment = median(samples_[0]), compute = median(samples_[1]);
    decided_ = true;
    compute_ = compute < fragment;
    std::snprintf(decision_.data(), decision_.size(), "%s path: %.3f ms against %.3f ms for the %s path (medians of %d timed frames)",
                  compute_ ? "compute" : "fragment", compute_ ? compute : fragment, compute_ ? fragment : compute,
                  compute_ ? "fragment" : "compute", kTrials);
    return {compute_, false};
  }
  // Alternate until each path has its trials in flight or done; then wait (fragment, untimed).
  const int issued = trials_started_;
  if (issued >= 2 * kTrials) return {false, false};
  return {issued % 2 == 1, true};
}

void PathChooser::begin(const Choice& choice) {
  active_ = -1;
  if (!choice.trial) return;
  const Functions& f = *gl_;
  GLint current = 0;
  f.GetQueryiv(TIME_ELAPSED, CURRENT_QUERY, &current);
  if (current != 0) return;  // the host times something: this frame is not a trial
  for (int i = 0; i < static_cast<int>(pending_.size()); ++i) {
    Pending& p = pending_[static_cast<std::size_t>(i)];
    if (p.waiting) continue;
    if (p.query == 0) f.GenQueries(1, &p.query);
    p.compute = choice.compute;
    f.BeginQuery(TIME_ELAPSED, p.query);
    active_ = i;
    return;
  }
}

void PathChooser::end() {
  if (active_ < 0) return;
  gl_->EndQuery(TIME_ELAPSED);
  pending_[static_cast<std::size_t>(active_)].waiting = true;
  active_ = -1;
  ++trials_started_;
}

}  // namespace sss::gl
