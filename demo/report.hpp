// Stage timings and the README.txt written beside the images.
#pragma once

#include "context.hpp"
#include "options.hpp"
#include "scene_view.hpp"

#include <sss/sss.h>

#include <string>
#include <vector>

namespace demo {

struct StageTiming {
  std::string name;
  double milliseconds;
};

class Timings {
 public:
  // Starts timing a stage (ends the previous one, if any). Call glFinish before for GL stages.
  void begin(const std::string &name);
  // Ends the current stage and prints "  name  12.3 ms".
  void end();
  const std::vector<StageTiming> &stages() const { return stages_; }

 private:
  std::vector<StageTiming> stages_;
  std::string current_;
  double started_ = 0.0;
  bool running_ = false;
};

struct ReportInput {
  const Options *options;
  const Context *context;
  const SceneView *view;
  const sss_settings *settings;
  float physical_width;  // sss_width_for_world_units_per_mm(0.001)
  const std::vector<StageTiming> *timings;
};

bool write_readme(const std::string &path, const ReportInput &input);

}  // namespace demo
