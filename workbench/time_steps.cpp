#include "workbench/time_steps.h"

#include <algorithm>
#include <utility>

#include "data/platform.h"

namespace ensil::workbench {

TimeSteps::TimeSteps(QObject* parent) : QObject(parent), m_budget(defaultBudget()) {}

std::size_t TimeSteps::defaultBudget() {
    constexpr std::size_t kMost = std::size_t{2} << 30;
    return std::min(kMost, data::availableMemoryBytes() / 4);
}

void TimeSteps::moved(std::size_t from, std::size_t to) {
    if (from != to) m_direction = to > from ? 1 : -1;
}

void TimeSteps::keep(std::size_t step, std::unique_ptr<engine::EnsembleOverview> overview,
                     std::size_t shown) {
    if (!overview) return;
    m_kept[step] = std::move(overview);
    const auto distance = [shown](std::size_t s) { return s > shown ? s - shown : shown - s; };
    std::size_t bytes = keptBytes();
    while (bytes > m_budget && m_kept.size() > 1) {
        const auto farthest = std::max_element(
            m_kept.begin(), m_kept.end(),
            [&](const auto& a, const auto& b) { return distance(a.first) < distance(b.first); });
        bytes -= farthest->second->ensemble->bytes();
        m_kept.erase(farthest);
    }
}

std::unique_ptr<engine::EnsembleOverview> TimeSteps::take(std::size_t step) {
    const auto found = m_kept.find(step);
    if (found == m_kept.end()) return nullptr;
    std::unique_ptr<engine::EnsembleOverview> overview = std::move(found->second);
    m_kept.erase(found);
    return overview;
}

const engine::EnsembleOverview* TimeSteps::kept(std::size_t step) const {
    const auto found = m_kept.find(step);
    return found == m_kept.end() ? nullptr : found->second.get();
}

std::vector<std::size_t> TimeSteps::keptSteps() const {
    std::vector<std::size_t> steps;
    for (const auto& [step, overview] : m_kept) steps.push_back(step);
    return steps;
}

std::size_t TimeSteps::keptBytes() const {
    std::size_t bytes = 0;
    for (const auto& [step, overview] : m_kept) bytes += overview->ensemble->bytes();
    return bytes;
}

std::optional<std::size_t> TimeSteps::nextToRead(std::size_t current, std::size_t count,
                                                 bool playing) const {
    if (count < 2 || current >= count) return std::nullopt;
    if (playing) return (current + 1) % count;
    if (m_direction > 0) {
        if (current + 1 >= count) return std::nullopt;
        return current + 1;
    }
    if (current == 0) return std::nullopt;
    return current - 1;
}

void TimeSteps::readAhead(std::size_t step, Reading reading) {
    if (m_reading == step) return;  // on its way
    m_reading = step;
    m_readAhead.start(
        std::move(reading),
        [this, step](engine::EnsembleOverview overview) {
            m_reading = kNone;
            m_kept[step] = std::make_unique<engine::EnsembleOverview>(std::move(overview));
            emit stepRead(step);
        },
        [this, step](const std::exception_ptr&, bool) {
            if (m_reading == step) m_reading = kNone;
        });
}

void TimeSteps::forget() {
    m_readAhead.cancel();
    m_reading = kNone;
    m_kept.clear();
}

std::optional<StepToCluster> nextStepToCluster(int current, int count,
                                               const std::function<bool(int)>& clustered) {
    for (int d = 1; d < count; ++d) {
        if (current + d < count && !clustered(current + d) && clustered(current + d - 1)) {
            return StepToCluster{current + d, current + d - 1};
        }
        if (current - d >= 0 && !clustered(current - d) && clustered(current - d + 1)) {
            return StepToCluster{current - d, current - d + 1};
        }
    }
    return std::nullopt;
}

}  // namespace ensil::workbench
