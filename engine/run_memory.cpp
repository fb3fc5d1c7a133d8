#include "engine/run_memory.h"

#include "data/platform.h"

namespace ensil::engine {

RunMemoryMeter::RunMemoryMeter() {
    if (data::resetPeakResidentMemory()) m_residentAtStart = data::residentMemoryBytes();
}

std::optional<RunMemory> RunMemoryMeter::read() const {
    if (!m_residentAtStart) return std::nullopt;
    const std::optional<std::size_t> peak = data::peakResidentMemoryBytes();
    if (!peak) return std::nullopt;
    return RunMemory{*m_residentAtStart, *peak};
}

}  // namespace ensil::engine
