#include "engine/run_memory.h"

#include <fstream>
#include <string>

namespace ensil::engine {
namespace {

// A "Key:   1234 kB" line of /proc/self/status, in bytes.
std::optional<std::size_t> statusBytes(const std::string& key) {
    std::ifstream status("/proc/self/status");
    std::string name;
    while (status >> name) {
        if (name == key + ":") {
            std::size_t kib = 0;
            if (status >> kib) return kib * 1024;
            return std::nullopt;
        }
        status.ignore(1 << 12, '\n');
    }
    return std::nullopt;
}

bool resetPeakResident() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5\n";
    clear.flush();
    return clear.good();
}

}  // namespace

RunMemoryMeter::RunMemoryMeter() {
    if (resetPeakResident()) m_residentAtStart = statusBytes("VmRSS");
}

std::optional<RunMemory> RunMemoryMeter::read() const {
    if (!m_residentAtStart) return std::nullopt;
    const std::optional<std::size_t> peak = statusBytes("VmHWM");
    if (!peak) return std::nullopt;
    return RunMemory{*m_residentAtStart, *peak};
}

}  // namespace ensil::engine
