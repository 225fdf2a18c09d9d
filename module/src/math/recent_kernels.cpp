#include "recent_kernels.hpp"

#include "spike_gaussian_profile.hpp"

namespace sss::math {

namespace {

// The entry whose key is the same as `key`, moved to the front; nullptr if none.
template <typename Key, typename Value, typename Same>
const Value* find_in(std::list<std::pair<Key, Value>>* list, const Key& key, Same same) {
  for (auto it = list->begin(); it != list->end(); ++it) {
    if (same(it->first, key)) {
      list->splice(list->begin(), *list, it);
      return &list->front().second;
    }
  }
  return nullptr;
}

template <typename Key, typename Value>
void keep_in(std::list<std::pair<Key, Value>>* list, const Key& key, const Value& value) {
  list->emplace_front(key, value);
  if (list->size() > RecentKernels::kCapacity) list->pop_back();
}

}  // namespace

bool same_cbf_kernel_inputs(const CbfKernelInputs& a, const CbfKernelInputs& b) {
  return a.profile == b.profile && a.taps == b.taps && a.r_max_mm == b.r_max_mm &&
         (a.profile != kKernelProfileId || same_profile_request(a.request, b.request));
}

const PassKernel* RecentKernels::find(const FilterSettings& settings) {
  return find_in(&pass_, settings, same_pass_kernel_inputs);
}

void RecentKernels::keep(const FilterSettings& settings, const PassKernel& kernel) {
  const KernelFamily family = settings.kernel.family;
  if (!builds_from_profile(family)) return;  // a closed form of its parameters: cheap
  if (find(settings) == nullptr) keep_in(&pass_, settings, kernel);
}

const CbfKernel* RecentKernels::find(const CbfKernelInputs& inputs) {
  return find_in(&cbf_, inputs, same_cbf_kernel_inputs);
}

void RecentKernels::keep(const CbfKernelInputs& inputs, const CbfKernel& kernel) {
  if (inputs.profile == kMikkelsenProfileId || inputs.profile == 0) return;  // closed form: cheap
  if (find(inputs) == nullptr) keep_in(&cbf_, inputs, kernel);
}

}  // namespace sss::math
