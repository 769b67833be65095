// The progress hook moved to kernel/progress.h so that every room (model, output, imaging) can
// report progress; this name stays for the methods' callers.
#pragma once
#include "kernel/progress.h"
