#include "profile_tables.hpp"

#include <algorithm>
#include <vector>

#include "debug_label.hpp"

namespace sss::gl {

namespace {
constexpr std::ptrdiff_t kTableBytes = static_cast<std::ptrdiff_t>(math::kProfileTableVectors) * 4 * sizeof(float);
}  // namespace

void ProfileTables::init(const Functions* gl, bool labels) {
  gl_ = gl;
  labels_ = labels;
  GLint max_block = 0, alignment = 0;
  gl_->GetIntegerv(MAX_UNIFORM_BLOCK_SIZE, &max_block);
  gl_->GetIntegerv(UNIFORM_BUFFER_OFFSET_ALIGNMENT, &alignment);
  capacity_ = static_cast<int>(std::min<std::ptrdiff_t>(math::kMaxProfiles, max_block / kTableBytes));
  const std::ptrdiff_t align = std::max<GLint>(alignment, 1);
  stride_ = (block_bytes() + align - 1) / align * align;
}

std::ptrdiff_t ProfileTables::block_bytes() const { return static_cast<std::ptrdiff_t>(capacity_) * kTableBytes; }

sss_result ProfileTables::upload(const FilterRun& run, std::string* message) {
  const Functions& f = *gl_;
  if (buffer_ == 0) {
    f.GenBuffers(1, &buffer_);
    f.BindBuffer(UNIFORM_BUFFER, buffer_);
    f.BufferData(UNIFORM_BUFFER, stride_ + block_bytes(), nullptr, DYNAMIC_DRAW);
    label_object(f, labels_, BUFFER, buffer_, "sss profile tables");
    if (f.GetError() == OUT_OF_MEMORY) {
      f.DeleteBuffers(1, &buffer_);
      buffer_ = 0;
      *message = "out of GL memory for the per-pixel profiles' tables";
      return SSS_ERROR_OUT_OF_MEMORY;
    }
    revision_ = 0;
  }
  if (revision_ == run.profiles_revision) return SSS_OK;  // a steady frame: no GL call here
  f.BindBuffer(UNIFORM_BUFFER, buffer_);
  std::vector<float> block(static_cast<std::size_t>(block_bytes() / static_cast<std::ptrdiff_t>(sizeof(float))), 0.0f);
  for (int axis = 0; axis < 2; ++axis) {
    for (int i = 0; i < run.profile_count && i < capacity_; ++i) {
      const math::PassTerm& term = run.profile_kernels[static_cast<std::size_t>(i)]->terms.front();
      math::pack_profile_table(axis == 0 ? term.horizontal : term.vertical,
                               block.data() + static_cast<std::size_t>(i) * math::kProfileTableVectors * 4);
    }
    f.BufferSubData(UNIFORM_BUFFER, axis * stride_, block_bytes(), block.data());
  }
  revision_ = run.profiles_revision;
  return SSS_OK;
}

void ProfileTables::bind(int axis) const {
  gl_->BindBufferRange(UNIFORM_BUFFER, 0, buffer_, axis == 0 ? 0 : stride_, block_bytes());
}

void ProfileTables::destroy() {
  if (gl_ != nullptr && buffer_ != 0) gl_->DeleteBuffers(1, &buffer_);
  forget();
}

void ProfileTables::forget() {
  buffer_ = 0;
  revision_ = 0;
}

}  // namespace sss::gl
