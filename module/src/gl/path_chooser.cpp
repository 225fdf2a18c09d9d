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

const char* path_name(int path) {
  switch (path) {
    case PathChooser::masked: return "masked fragment";
    case PathChooser::half: return "half-resolution";
    case PathChooser::compute: return "compute";
    default: return "fragment";
  }
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

void PathChooser::prewarm() {
  if (!timer_) return;
  for (Pending& p : pending_) {
    if (p.query == 0) gl_->GenQueries(1, &p.query);
  }
}

void PathChooser::reset(std::uint64_t key) {
  key_ = key;
  has_key_ = true;
  decided_ = false;
  trials_started_ = 0;
  for (auto& v : samples_) {
    v.clear();
    v.reserve(pending_.size());  // every pending query's result fits: no allocation after the first reset
  }
  // Results of an earlier configuration's trials still in flight are dropped (the query objects
  // are simply begun again later).
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
    samples_[static_cast<std::size_t>(p.path)].push_back(static_cast<double>(ns) * 1e-6);
  }
}

PathChooser::Choice PathChooser::choose(std::uint64_t key, unsigned available, bool region) {
  decision_[0] = '\0';
  available |= 1u << fragment;
  key = key * 31u + available;  // a path becoming (un)available is a new configuration
  if (!has_key_ || key != key_) reset(key);
  if (decided_) return {chosen_, false};
  if (!timer_) {
    decided_ = true;
    chosen_ = (available & (1u << masked)) != 0 && !region ? masked : fragment;
    std::snprintf(decision_.data(), decision_.size(),
                  "%s path (no trustworthy timer here; the benchmark measured it the fastest on software "
                  "rasterisers %s)",
                  path_name(chosen_), region ? "given a region" : "without a region");
    return {chosen_, false};
  }
  collect();
  int candidates[kPaths];
  int count = 0;
  for (int p = 0; p < kPaths; ++p) {
    if ((available & (1u << p)) != 0) candidates[count++] = p;
  }
  bool complete = true;
  for (int i = 0; i < count; ++i) {
    complete = complete && static_cast<int>(samples_[static_cast<std::size_t>(candidates[i])].size()) >= kTrials;
  }
  if (complete) {
    int best = candidates[0];
    for (int i = 1; i < count; ++i) {
      if (median(samples_[static_cast<std::size_t>(candidates[i])]) < median(samples_[static_cast<std::size_t>(best)])) {
        best = candidates[i];
      }
    }
    decided_ = true;
    chosen_ = best;
    int n = std::snprintf(decision_.data(), decision_.size(), "%s path (medians of %d timed frames:", path_name(best),
                          kTrials);
    for (int i = 0; i < count && n > 0 && n < static_cast<int>(decision_.size()); ++i) {
      n += std::snprintf(decision_.data() + n, decision_.size() - static_cast<std::size_t>(n), " %s %.3f ms",
                         path_name(candidates[i]), median(samples_[static_cast<std::size_t>(candidates[i])]));
    }
    if (n > 0 && n + 1 < static_cast<int>(decision_.size())) std::snprintf(decision_.data() + n, 2, ")");
    return {chosen_, false};
  }
  // Cycle through the candidates until each has its trials in flight or done; then wait on the
  // plain fragment path, untimed.
  if (trials_started_ >= kTrials * count) return {fragment, false};
  return {candidates[trials_started_ % count], true};
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
    p.path = choice.path;
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
