// The time steps of the data on screen besides the one shown (issue 17): the next step read
// ahead in the background, in the direction of the user's last move (round the end while
// playing), and the steps visited before kept, within a memory budget that drops the steps
// farthest from the one shown first, so that going back to a step costs only its surfaces. How
// a step is read is the caller's (a job's work per step). Also the order in which the cluster
// strip's steps are filled. Widget-free; GUI thread.
#pragma once

#include <QObject>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "engine/ensemble_overview.h"
#include "workbench/background_job.h"

namespace ensil::workbench {

class TimeSteps : public QObject {
    Q_OBJECT
public:
    using Reading = BackgroundJob<engine::EnsembleOverview>::Work;

    explicit TimeSteps(QObject* parent = nullptr);

    // What the steps kept may take by default: a quarter of the memory available now, at most
    // 2 GiB (the step read ahead is always kept: reading ahead is what makes playing smooth).
    [[nodiscard]] static std::size_t defaultBudget();
    void setBudget(std::size_t bytes) { m_budget = bytes; }

    // A move between steps: reading ahead follows its direction.
    void moved(std::size_t from, std::size_t to);
    [[nodiscard]] int direction() const { return m_direction; }

    // Keeps a step that was left (it may be visited again); then, while the steps kept take
    // more than the budget, drops the one farthest from `shown` (one step always stays).
    void keep(std::size_t step, std::unique_ptr<engine::EnsembleOverview> overview,
              std::size_t shown);
    // A kept step, taken out to be shown (null when it is not kept).
    [[nodiscard]] std::unique_ptr<engine::EnsembleOverview> take(std::size_t step);
    [[nodiscard]] const engine::EnsembleOverview* kept(std::size_t step) const;
    [[nodiscard]] std::vector<std::size_t> keptSteps() const;
    // Their ensembles' bytes (a thinned copy's when the data are streamed).
    [[nodiscard]] std::size_t keptBytes() const;

    // The step to read ahead of `current` among `count`: the next in the direction of the last
    // move, round the end while playing; none at an end, or with fewer than two steps.
    [[nodiscard]] std::optional<std::size_t> nextToRead(std::size_t current, std::size_t count,
                                                        bool playing) const;
    // Reads `step` in the background with `reading` (a step already on its way is left to
    // finish); stepRead(step) follows and the step is then kept (beyond the budget). A failure
    // keeps nothing and says nothing: reading ahead is a guess, and a step that cannot be read
    // says so when it is asked for.
    void readAhead(std::size_t step, Reading reading);
    [[nodiscard]] bool isReading(std::size_t step) const { return m_reading == step; }
    [[nodiscard]] bool isReadingAny() const { return m_reading != kNone; }

    // Other data: stops reading and forgets every step kept.
    void forget();

signals:
    void stepRead(std::size_t step);

private:
    static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::map<std::size_t, std::unique_ptr<engine::EnsembleOverview>> m_kept;
    BackgroundJob<engine::EnsembleOverview> m_readAhead{this};
    // The step being read, from the job's start (queued behind other work, a job does not count
    // as running yet) to its end; kNone when none.
    std::size_t m_reading = kNone;
    std::size_t m_budget;
    int m_direction = 1;  // of the last move: +1 later, -1 earlier
};

// The cluster strip's next step to cluster in the background, of `count` steps with `current`
// shown: the nearest step not clustered that lies next to one that is, later steps first, with
// that neighbour (between it and the step shown), so that each is matched to its neighbour's
// identities and they follow the groups outward. None when every step reachable is clustered.
struct StepToCluster {
    int step = -1;
    int neighbour = -1;
};
[[nodiscard]] std::optional<StepToCluster> nextStepToCluster(
    int current, int count, const std::function<bool(int)>& clustered);

}  // namespace ensil::workbench
