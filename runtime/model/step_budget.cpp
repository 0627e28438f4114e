#include "runtime/model/step_budget.h"

namespace ks::runtime {

bool StepBudget::take() {
    if (used_ >= max_) {
        ++dropped_;
        return false;
    }
    ++used_;
    return true;
}

} // namespace ks::runtime
