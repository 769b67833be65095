// 4x4 supersampling (reconstruct.h), band by band of pixel rows. Private to reconstruct.cpp.
#pragma once
#include "algorithms/imaging/image.h"
#include "algorithms/model/model.h"
#include "algorithms/model/prepared_model.h"
#include "kernel/progress.h"

namespace erd {

// Renders the prepared model m into *out (its size, channels and maxval, zeroed) by 4x4
// supersampling; threads: bands of rows side by side, the same image for every count.
void supersampling(const Model& m, const PreparedModel& p, Image* out, ProgressHook progress, int threads);

}  // namespace erd
