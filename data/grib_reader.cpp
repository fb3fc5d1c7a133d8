#include "data/grib_reader.h"

#include <filesystem>
#include <list>
#include <memory>
#include <mutex>

#include "data/content_hash.h"
#include "data/error.h"
#include "data/grib_messages.h"
#include "data/grib_plan.h"
#include "data/reader_support.h"

namespace ensil::data {
namespace {

std::string formatOf(const GribInventory& inventory) {
    bool one = false, two = false;
    for (const GribMessage& m : inventory.messages) {
        one = one || m.edition == 1;
        two = two || m.edition == 2;
    }
    return one && two ? "GRIB 1 and 2" : two ? "GRIB 2" : "GRIB 1";
}

// The messages of a file, scanned once for openEnsemble()'s describe() and read() and for the
// Open dialog's repeated descriptions: ecCodes takes milliseconds a message to say what it
// holds, hashing the file's bytes far less. The last few files are kept, each under its path
// and the hash of its contents (a file rewritten with its size and time kept is other data).
std::shared_ptr<const GribInventory> inventoryOf(const std::string& path,
                                                 const std::stop_token& stop) {
    std::error_code error;
    const std::string key =
        std::filesystem::absolute(path, error).string() + '\n' + std::to_string(contentHash(path));
    static std::mutex mutex;
    static std::list<std::pair<std::string, std::shared_ptr<const GribInventory>>> recent;
    constexpr std::size_t kFilesKept = 4;
    {
        const std::lock_guard lock(mutex);
        for (const auto& [k, inventory] : recent) {
            if (k == key) return inventory;
        }
    }
    auto inventory = std::make_shared<const GribInventory>(scanGribFile(path, stop));
    const std::lock_guard lock(mutex);
    recent.emplace_front(key, inventory);
    if (recent.size() > kFilesKept) recent.pop_back();
    return inventory;
}

// The plan; a refusal names every message the scan skipped as damaged, since a damaged
// message is often why a variable lacks a level, a member or a time ("'t' has one level only"
// where the other level's message was the damaged one).
GribPlan planWithSkippedMessagesNamed(const GribInventory& inventory, const std::string& path,
                                      const DataSelection& selection) {
    try {
        return planGribVariable(inventory, path, selection);
    } catch (const Error& e) {
        // Those the refusal does not name already (a missing field's refusal names them).
        const std::string what = e.what();
        std::vector<std::string> unnamed;
        for (const std::string& w : inventory.warnings) {
            if (what.find(w) == std::string::npos) unnamed.push_back(w);
        }
        if (unnamed.empty()) throw;
        constexpr std::size_t kNamed = 10;
        std::string skipped;
        for (std::size_t i = 0; i < unnamed.size() && i < kNamed; ++i) {
            skipped += (i == 0 ? "" : "; ") + unnamed[i];
        }
        if (unnamed.size() > kNamed) {
            skipped += "; and " + std::to_string(unnamed.size() - kNamed) + " more";
        }
        const std::size_t n = unnamed.size();
        throw Error(e.kind(),
                    what + ". " + std::to_string(n) + (n == 1 ? " message was" : " messages were") +
                        " skipped as damaged, which may be why: " + skipped,
                    e.choices());
    }
}

// The files' inventories and plans, and what they say together. The plans point into the
// inventories, which therefore stay where they are.
struct OpenedFiles {
    std::vector<std::shared_ptr<const GribInventory>> inventories;
    std::vector<GribPlan> plans;
    EnsembleDescription description;
};

OpenedFiles openFiles(const DataSelection& selection, const std::stop_token& stop) {
    requireFiles(selection.paths);
    const bool oneFile = selection.paths.size() == 1;
    const std::vector<std::string> stems = memberNamesFromPaths(selection.paths);
    OpenedFiles opened;
    EnsembleDescription& d = opened.description;
    std::string firstLabel;  // the first file's step at the time index
    for (std::size_t f = 0; f < selection.paths.size(); ++f) {
        const std::string& path = selection.paths[f];
        const GribInventory& inventory = *opened.inventories.emplace_back(inventoryOf(path, stop));
        const GribPlan& plan =
            opened.plans.emplace_back(planWithSkippedMessagesNamed(inventory, path, selection));
        if (f == 0) {
            d.format = formatOf(inventory);
            d.variables = listGribVariables(inventory, path);
            d.variable = plan.name;
            d.longName = plan.longName;
            d.units = plan.units;
            d.grid = plan.grid;
            d.fixedDimensions = plan.fixedDimensions;
            d.timeSteps = plan.timeSteps;
            if (selection.timeIndex < d.timeSteps.count()) {
                firstLabel = d.timeSteps.labels[selection.timeIndex];
            }
            d.memberDimension = plan.memberDimension;
            d.memberDimensionReason = oneFile ? plan.memberReason : "one file per member";
        } else {
            if (plan.name != d.variable) {
                throw Error(ErrorKind::InvalidArgument,
                            "'" + path + "' holds '" + plan.name + "' where '" +
                                selection.paths.front() + "' holds '" + d.variable +
                                "': every member file must hold the same variable; name it "
                                "with --var (the Variable box of the Open dialog)");
            }
            checkSameGrid(selection.paths.front(), d.grid, path, plan.grid);
            noteTimesThatDiffer(d, selection.timeIndex, firstLabel, selection.paths.front(),
                                plan.timeSteps, path);
        }
        if (oneFile && plan.oneMember && plan.memberDimension == "number") {
            throw Error(ErrorKind::MemberDimensionNotFound,
                        "'" + path + "' holds one member of '" + plan.name + "' (" +
                            plan.memberNames.front() +
                            "): open one file per member, or, if its times stand in for "
                            "members, say so with --member-dim time",
                        {"time"});
        }
        std::vector<std::string> names = plan.memberNames;
        if (!oneFile) {
            // One forecast per file: the file names it; several: the file and the number.
            if (plan.oneMember && plan.memberDimension == "number") {
                names = {stems[f]};
            } else {
                for (std::string& n : names) n.insert(0, stems[f] + " ");
            }
        }
        d.members += names.size();
        d.memberNames.insert(d.memberNames.end(), names.begin(), names.end());
        d.warnings.insert(d.warnings.end(), inventory.warnings.begin(), inventory.warnings.end());
    }
    return opened;
}

}  // namespace

bool GribReader::recognizes(const std::string& path) const {
    return startsWith(readFileStart(path, 4), "GRIB");
}

EnsembleDescription GribReader::describe(const DataSelection& selection) const {
    return openFiles(selection, {}).description;
}

Ensemble GribReader::read(const DataSelection& selection, const std::stop_token& stop,
                          const Progress& progress) const {
    const OpenedFiles opened = openFiles(selection, stop);
    const EnsembleDescription& d = opened.description;
    checkMemoryFor(d.bytes(), "'" + d.variable + "' (" + std::to_string(d.members) +
                                  " members of " +
                                  shapeText(d.grid.nx(), d.grid.ny(), d.grid.nz()) + " points)");
    Ensemble e = ensembleDescribedBy(d, selection.paths);
    const std::size_t layer = d.grid.nx() * d.grid.ny();
    std::size_t total = 0, done = 0;
    for (const GribPlan& plan : opened.plans) {
        total += plan.fields.size() * d.grid.nz() * (plan.derived ? 2 : 1);
    }
    std::vector<double> scratch;
    std::vector<float> v;
    std::size_t next = 0;
    for (std::size_t f = 0; f < opened.plans.size(); ++f) {
        const GribPlan& plan = opened.plans[f];
        const GribFile file(selection.paths[f]);
        for (const auto& levels : plan.fields) {
            Member& member = e.members.at(next);
            member.name = d.memberNames.at(next++);
            member.values.resize(d.grid.pointCount());
            for (std::size_t k = 0; k < levels.size(); ++k) {
                float* out = member.values.data() + k * layer;
                throwIfStopped(stop);
                file.decode(*levels[k][0], out, scratch);
                if (plan.derived) {
                    v.resize(layer);
                    throwIfStopped(stop);
                    file.decode(*levels[k][1], v.data(), scratch);
                    toWindSpeed(out, v.data(), layer);
                }
                done += plan.derived ? 2 : 1;
                report(progress, static_cast<double>(done) / static_cast<double>(total));
            }
        }
    }
    return e;
}

}  // namespace ensil::data
