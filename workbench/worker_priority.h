// Background work yields the processor to the GUI thread. On a machine with few cores, jobs
// that keep every core busy (marching cubes and decimation run in parallel) leave the GUI thread
// and the OpenGL driver's threads (llvmpipe rasterises on the CPU) waiting for a core, so a
// window repaint that takes 30 ms on an idle machine takes 100-200 ms. A worker that calls
// lowerThisThreadPriority() runs at nice 19 (Linux: nice is per thread, and threads it starts,
// such as oneTBB's workers, inherit it), so the GUI wins the processor when it needs it and
// the workers still get all of it otherwise. Any thread; a no-op elsewhere than Linux.
#pragma once

namespace ensil::workbench {

// The nice value background work runs at.
inline constexpr int kWorkerNice = 19;

// Lowers the calling thread to kWorkerNice (never raises it). Returns false when the system
// refused or does not support it; the work runs at normal priority then.
bool lowerThisThreadPriority();

}  // namespace ensil::workbench
