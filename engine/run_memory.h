#pragma once
// The resident memory one command's run takes, read from the kernel: `ensil preprocess`
// reports it (--json "memory"), so a user can choose --memory-limit from what a run took, and
// the memory-bound test reads the program's own figure.
#include <cstddef>
#include <optional>

namespace ensil::engine {

struct RunMemory {
    std::size_t residentAtStart = 0;  // bytes resident when the run began (libraries, Qt)
    std::size_t peakResident = 0;     // the most resident at once since then, those included
};

// Constructed where the run begins: it resets the kernel's peak-resident counter there
// (Linux: /proc/self/clear_refs, "5"), so the peak is this run's, not the program's start-up
// or a parent's pages the process held before exec. Where the counter cannot be reset (not
// Linux, or /proc not writable) there is no figure rather than a wrong one.
class RunMemoryMeter {
public:
    RunMemoryMeter();
    std::optional<RunMemory> read() const;

private:
    std::optional<std::size_t> m_residentAtStart;
};

}  // namespace ensil::engine
