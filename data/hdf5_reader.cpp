#include "data/hdf5_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "data/error.h"
#include "data/hdf5_file.h"
#include "data/reader_support.h"

namespace ensil::data {
namespace {

using hdf5::Attributes;
using hdf5::DatasetInfo;
using hdf5::File;

const std::string kNeeds = "ensil needs (member, z, y, x) or one (z, y, x) dataset per member";

enum class Layout { FourDimensional, MemberGroup, SingleDataset, FilePerMember };

// What a selection resolves to: where each member's values live and what to call them.
struct Plan {
    Layout layout = Layout::SingleDataset;
    std::string object;                 // the chosen dataset or group
    std::vector<std::string> datasets;  // MemberGroup: one dataset path per member
    std::vector<std::string> memberNames;
    std::vector<std::size_t> shape;  // z, y, x
    Attributes attributes;
    Grid grid;
    std::string variable;
    std::string memberDimension;
    std::string reason;
};

struct MemberGroup {
    std::string path;
    std::vector<DatasetInfo> datasets;  // ordered by name
    std::string problem;                // empty when usable
    bool shapesDiffer = false;
};

std::string parentOf(const std::string& path) {
    const auto slash = path.rfind('/');
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::vector<std::size_t> spatialShape(const std::vector<std::size_t>& shape) {
    return {shape.end() - 3, shape.end()};
}

std::string zyxText(const std::vector<std::size_t>& zyx) {
    return shapeText(zyx[2], zyx[1], zyx[0]);
}

// Empty when the dataset can make an ensemble, else why not in plain words.
std::string whyNotUsable(const DatasetInfo& d) {
    if (!d.typeProblem.empty()) {
        return "dataset '" + d.path + "' holds " + d.typeProblem +
               ": ensil needs integer or floating-point values";
    }
    if (d.shape.size() != 3 && d.shape.size() != 4) {
        return "dataset '" + d.path + "' has rank " + std::to_string(d.shape.size()) + ": " +
               kNeeds;
    }
    const auto zyx = spatialShape(d.shape);
    if (std::ranges::any_of(zyx, [](std::size_t n) { return n < 2; })) {
        return "dataset '" + d.path + "' is " + zyxText(zyx) +
               " (x by y by z): isosurfaces need at least 2 points along every axis";
    }
    if (d.shape.size() == 4 && d.shape[0] == 0) return "dataset '" + d.path + "' has no members";
    return {};
}

// Name order with runs of digits compared by value, so member m2 comes before m10 (h5py files
// often number members without leading zeros). Equal by that rule, plain order decides.
bool naturalLess(const std::string& a, const std::string& b) {
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (digit(a[i]) && digit(b[j])) {
            std::size_t ie = i, je = j;
            while (ie < a.size() && digit(a[ie])) ++ie;
            while (je < b.size() && digit(b[je])) ++je;
            std::size_t is = i, js = j;  // past leading zeros
            while (is + 1 < ie && a[is] == '0') ++is;
            while (js + 1 < je && b[js] == '0') ++js;
            const std::string_view x(a.data() + is, ie - is), y(b.data() + js, je - js);
            if (x.size() != y.size()) return x.size() < y.size();
            if (x != y) return x < y;
            i = ie;
            j = je;
        } else {
            if (a[i] != b[j]) return a[i] < b[j];
            ++i;
            ++j;
        }
    }
    if ((i < a.size()) != (j < b.size())) return j < b.size();
    return a < b;
}

bool isMemberCandidate(const DatasetInfo& d) {
    return d.shape.size() == 3 && d.typeProblem.empty();
}

// Groups whose direct children include (z, y, x) datasets; `minimum` of them to count.
std::vector<MemberGroup> memberGroups(const File::Contents& contents, std::size_t minimum) {
    std::vector<MemberGroup> groups;
    for (const std::string& group : contents.groups) {
        MemberGroup g{group, {}, {}};
        for (const DatasetInfo& d : contents.datasets) {
            if (parentOf(d.path) == group && isMemberCandidate(d)) g.datasets.push_back(d);
        }
        if (g.datasets.size() < minimum || g.datasets.empty()) continue;
        std::ranges::sort(g.datasets, [](const DatasetInfo& x, const DatasetInfo& y) {
            return naturalLess(x.path, y.path);
        });
        for (const DatasetInfo& d : g.datasets) {
            if (d.shape != g.datasets.front().shape) {
                g.problem = "datasets in group '" + group + "' differ in shape: '" +
                            g.datasets.front().path + "' is " + zyxText(g.datasets.front().shape) +
                            ", '" + d.path + "' is " + zyxText(d.shape) + " (x by y by z)";
                g.shapesDiffer = true;
                break;
            }
        }
        if (g.problem.empty()) g.problem = whyNotUsable(g.datasets.front());
        groups.push_back(std::move(g));
    }
    return groups;
}

Grid makeGrid(const Attributes& a, const std::vector<std::size_t>& zyx, const std::string& where) {
    requireThreeDimensional(where, zyx[2], zyx[1], zyx[0]);
    const std::array<double, 3> origin = a.origin.value_or(std::array<double, 3>{0, 0, 0});
    const std::array<double, 3> spacing = a.spacing.value_or(std::array<double, 3>{1, 1, 1});
    try {
        return Grid(uniformAxis("x", origin[0], spacing[0], zyx[2]),
                    uniformAxis("y", origin[1], spacing[1], zyx[1]),
                    uniformAxis("z", origin[2], spacing[2], zyx[0]));
    } catch (const Error& e) {
        throw Error(ErrorKind::InvalidArgument,
                    where + ": " + e.what() + " (check its 'origin' and 'spacing' attributes)");
    }
}

std::string where(const File& file, const std::string& object) {
    return "'" + object + "' in '" + file.path() + "'";
}

// A group's own attributes win; those it lacks come from its first dataset.
Attributes groupAttributes(const File& file, const MemberGroup& group) {
    Attributes a = file.attributes(group.path);
    const Attributes first = file.attributes(group.datasets.front().path);
    if (a.units.empty()) a.units = first.units;
    if (a.longName.empty()) a.longName = first.longName;
    if (!a.origin) a.origin = first.origin;
    if (!a.spacing) a.spacing = first.spacing;
    return a;
}

std::string variableName(const std::string& object, const std::string& filePath) {
    const std::string base = hdf5::baseName(object);
    return base.empty() ? std::filesystem::path(filePath).stem().string() : base;
}

Plan datasetPlan(const File& file, const DatasetInfo& d) {
    if (const std::string problem = whyNotUsable(d); !problem.empty()) {
        const std::string message = problem + " (in '" + file.path() + "')";
        if (!d.typeProblem.empty()) throw Error(ErrorKind::UnsupportedFormat, message);
        if (d.shape.size() == 3 || d.shape.size() == 4) {
            const auto zyx = spatialShape(d.shape);
            requireThreeDimensional(where(file, d.path), zyx[2], zyx[1], zyx[0]);
            throw Error(ErrorKind::InvalidArgument, message);  // no members
        }
        throw Error(ErrorKind::NotThreeDimensional, message);
    }
    Plan plan;
    plan.object = d.path;
    plan.shape = spatialShape(d.shape);
    plan.attributes = file.attributes(d.path);
    plan.variable = variableName(d.path, file.path());
    if (d.shape.size() == 4) {
        plan.layout = Layout::FourDimensional;
        for (std::size_t m = 0; m < d.shape[0]; ++m) {
            plan.memberNames.push_back("member " + std::to_string(m + 1));
        }
        plan.memberDimension = "member";
        plan.reason = "first dimension of the 4D dataset '" + d.path + "' (member, z, y, x)";
    } else {
        plan.layout = Layout::SingleDataset;
        plan.memberNames = {plan.variable};
    }
    plan.grid = makeGrid(plan.attributes, plan.shape, where(file, d.path));
    return plan;
}

Plan groupPlan(const File& file, const MemberGroup& group) {
    if (group.shapesDiffer) {
        throw Error(ErrorKind::GridMismatch, group.problem + " (in '" + file.path() + "')");
    }
    Plan plan;
    plan.layout = Layout::MemberGroup;
    plan.object = group.path;
    plan.shape = group.datasets.front().shape;
    for (const DatasetInfo& d : group.datasets) {
        plan.datasets.push_back(d.path);
        plan.memberNames.push_back(hdf5::baseName(d.path));
    }
    plan.attributes = groupAttributes(file, group);
    plan.variable = variableName(group.path, file.path());
    plan.memberDimension = group.path;
    plan.reason = "one (z, y, x) dataset per member in group '" + group.path + "'";
    plan.grid = makeGrid(plan.attributes, plan.shape, where(file, group.path));
    return plan;
}

std::vector<std::string> usableNames(const File::Contents& contents) {
    std::vector<std::string> names;
    for (const DatasetInfo& d : contents.datasets) {
        if (d.shape.size() == 4 && whyNotUsable(d).empty()) names.push_back(d.path);
    }
    for (const MemberGroup& g : memberGroups(contents, 2)) {
        if (g.problem.empty()) names.push_back(g.path);
    }
    for (const DatasetInfo& d : contents.datasets) {
        if (d.shape.size() == 3 && whyNotUsable(d).empty()) names.push_back(d.path);
    }
    return names;
}

[[noreturn]] void throwNothingUsable(const File& file, const File::Contents& contents) {
    if (contents.datasets.empty()) {
        throw Error(ErrorKind::VariableNotFound, "'" + file.path() + "' holds no datasets");
    }
    std::string reasons;
    for (const DatasetInfo& d : contents.datasets) reasons += "; " + whyNotUsable(d);
    throw Error(ErrorKind::NotThreeDimensional,
                "no dataset in '" + file.path() + "' can make an ensemble" + reasons);
}

// The first usable 4D dataset, else the first group of two or more (z, y, x) datasets, in the
// depth-first name order of the file; when the file holds more than one such ensemble, the
// reason names them all and how to choose another.
Plan automaticPlan(const File& file, const File::Contents& contents) {
    std::vector<std::string> ensembles;
    std::optional<Plan> plan;
    for (const DatasetInfo& d : contents.datasets) {
        if (d.shape.size() != 4 || !whyNotUsable(d).empty()) continue;
        ensembles.push_back(d.path);
        if (!plan) plan = datasetPlan(file, d);
    }
    for (const MemberGroup& g : memberGroups(contents, 2)) {
        if (!g.problem.empty()) continue;
        ensembles.push_back(g.path);
        if (!plan) plan = groupPlan(file, g);
    }
    if (plan) {
        if (ensembles.size() > 1) {
            plan->reason += "; the first of the " + std::to_string(ensembles.size()) +
                            " ensembles in the file (" + quotedList(ensembles) +
                            "): name another with --var (the Variable box of the Open dialog)";
        }
        return *plan;
    }
    for (const DatasetInfo& d : contents.datasets) {
        if (d.shape.size() == 3 && whyNotUsable(d).empty()) return datasetPlan(file, d);
    }
    throwNothingUsable(file, contents);
}

Plan singleFilePlan(const File& file, const std::string& requested) {
    const File::Contents contents = file.contents();
    if (requested.empty()) return automaticPlan(file, contents);
    const std::string path = hdf5::normalizePath(requested);
    for (const DatasetInfo& d : contents.datasets) {
        if (d.path == path) return datasetPlan(file, d);
    }
    for (const MemberGroup& g : memberGroups(contents, 1)) {
        if (g.path == path) return groupPlan(file, g);
    }
    const std::string what = file.isGroup(path) ? "group '" + path + "' holds no (z, y, x) dataset"
                                                : "no dataset or group '" + path + "'";
    throw Error(ErrorKind::VariableNotFound,
                what + " in '" + file.path() + "'; usable: " + quotedList(usableNames(contents)));
}

std::string firstThreeDimensional(const File& file) {
    const File::Contents contents = file.contents();
    for (const DatasetInfo& d : contents.datasets) {
        if (d.shape.size() == 3 && whyNotUsable(d).empty()) return d.path;
    }
    throwNothingUsable(file, contents);
}

// Checks every file holds the dataset with the first file's shape and grid.
void checkMemberFile(const std::string& path, const Plan& plan, const std::string& firstPath) {
    const File file(path);
    if (!file.isDataset(plan.object)) {
        throw Error(ErrorKind::VariableNotFound, "'" + path + "' has no dataset '" + plan.object +
                                                     "' (found in '" + firstPath +
                                                     "'): every member file needs it; it holds " +
                                                     quotedList(usableNames(file.contents())));
    }
    const DatasetInfo d = file.inspect(plan.object);
    if (d.shape != plan.shape) {
        const std::string shape =
            d.shape.size() == 3 ? zyxText(d.shape) : "rank " + std::to_string(d.shape.size());
        throw Error(ErrorKind::GridMismatch,
                    "dataset '" + plan.object + "' is " + zyxText(plan.shape) + " in '" +
                        firstPath + "' but " + shape + " in '" + path +
                        "' (x by y by z): every member file needs the same grid");
    }
    const Grid grid = makeGrid(file.attributes(plan.object), d.shape, where(file, d.path));
    if (!grid.sameShapeAndCoordinates(plan.grid)) {
        throw Error(ErrorKind::GridMismatch,
                    "dataset '" + plan.object + "' has other coordinates in '" + path +
                        "' than in '" + firstPath + "' (compare their 'origin' and 'spacing')");
    }
}

Plan filePerMemberPlan(const std::vector<std::string>& paths, const std::string& requested) {
    const File first(paths.front());
    const std::string object =
        requested.empty() ? firstThreeDimensional(first) : hdf5::normalizePath(requested);
    if (!first.isDataset(object)) {
        throw Error(ErrorKind::VariableNotFound,
                    "no dataset '" + object + "' in '" + first.path() +
                        "'; usable: " + quotedList(usableNames(first.contents())));
    }
    const DatasetInfo d = first.inspect(object);
    if (d.shape.size() != 3) {
        throw Error(ErrorKind::NotThreeDimensional,
                    "dataset '" + object + "' in '" + first.path() + "' has rank " +
                        std::to_string(d.shape.size()) +
                        ": with one file per member each file needs one (z, y, x) dataset");
    }
    Plan plan = datasetPlan(first, d);
    plan.layout = Layout::FilePerMember;
    plan.memberNames = memberNamesFromPaths(paths);
    for (std::size_t i = 1; i < paths.size(); ++i) checkMemberFile(paths[i], plan, paths.front());
    return plan;
}

Plan makePlan(const DataSelection& selection) {
    requireFiles(selection.paths);
    if (selection.paths.size() == 1) {
        return singleFilePlan(File(selection.paths.front()), selection.variable);
    }
    return filePerMemberPlan(selection.paths, selection.variable);
}

VariableInfo datasetVariable(const File& file, const DatasetInfo& d) {
    VariableInfo v;
    v.name = d.path;
    v.shape = d.shape;
    if (d.shape.size() == 4) v.dimensions = {"member", "z", "y", "x"};
    if (d.shape.size() == 3) v.dimensions = {"z", "y", "x"};
    for (std::size_t i = v.dimensions.size(); i < d.shape.size(); ++i) {
        v.dimensions.push_back("dim" + std::to_string(i));
    }
    v.whyNotUsable = whyNotUsable(d);
    try {
        const Attributes a = file.attributes(d.path);
        v.units = a.units;
        v.longName = a.longName;
    } catch (const Error& e) {
        if (v.whyNotUsable.empty()) v.whyNotUsable = e.what();
    }
    v.usable = v.whyNotUsable.empty();
    return v;
}

std::vector<VariableInfo> listVariables(const File& file) {
    const File::Contents contents = file.contents();
    std::vector<VariableInfo> variables;
    for (const DatasetInfo& d : contents.datasets) variables.push_back(datasetVariable(file, d));
    for (const MemberGroup& g : memberGroups(contents, 2)) {
        VariableInfo v;
        v.name = g.path;
        v.dimensions = {"member", "z", "y", "x"};
        const std::vector<std::size_t>& zyx = g.datasets.front().shape;
        v.shape = {g.datasets.size(), zyx[0], zyx[1], zyx[2]};
        v.whyNotUsable = g.problem;
        v.usable = g.problem.empty();
        variables.push_back(std::move(v));
    }
    return variables;
}

void markMissing(FieldValues& values, const std::vector<double>& missing) {
    for (const double m : missing) {
        const auto marker = static_cast<float>(m);
        if (std::isnan(marker)) continue;
        for (float& v : values) {
            if (v == marker) v = std::numeric_limits<float>::quiet_NaN();
        }
    }
}

// `file` is the open single file, or null with one file per member.
void readMember(const File* file, const DataSelection& selection, const Plan& plan, std::size_t m,
                FieldValues& values) {
    const std::vector<std::size_t> zero{0, 0, 0};
    if (!file) {
        const File memberFile(selection.paths[m]);
        memberFile.read(plan.object, zero, plan.shape, values.data());
        markMissing(values, memberFile.attributes(plan.object).missingValues);
        return;
    }
    if (plan.layout == Layout::MemberGroup) {
        file->read(plan.datasets[m], zero, plan.shape, values.data());
        markMissing(values, file->attributes(plan.datasets[m]).missingValues);
    } else if (plan.layout == Layout::FourDimensional) {
        const std::vector<std::size_t> start{m, 0, 0, 0};
        const std::vector<std::size_t> count{1, plan.shape[0], plan.shape[1], plan.shape[2]};
        file->read(plan.object, start, count, values.data());
    } else {
        file->read(plan.object, zero, plan.shape, values.data());
    }
    markMissing(values, plan.attributes.missingValues);
}

}  // namespace

bool Hdf5Reader::recognizes(const std::string& path) const {
    return readFileStart(path, 8) == std::string_view("\x89HDF\r\n\x1a\n", 8);
}

EnsembleDescription Hdf5Reader::describe(const DataSelection& selection) const {
    const hdf5::QuietErrors quiet;
    const Plan plan = makePlan(selection);
    EnsembleDescription d;
    d.format = "HDF5";
    d.variables = listVariables(File(selection.paths.front()));
    d.variable = plan.object;
    d.longName = plan.attributes.longName;
    d.units = plan.attributes.units;
    d.memberDimension = plan.memberDimension;
    d.memberDimensionReason = plan.reason;
    d.members = plan.memberNames.size();
    d.memberNames = plan.memberNames;
    d.grid = plan.grid;
    return d;
}

Ensemble Hdf5Reader::read(const DataSelection& selection, const std::stop_token& stop,
                          const Progress& progress) const {
    const hdf5::QuietErrors quiet;
    const Plan plan = makePlan(selection);
    Ensemble e;
    e.variable = plan.variable;
    e.longName = plan.attributes.longName;
    e.units = plan.attributes.units;
    e.memberDimension = plan.memberDimension;
    e.source = sourceOf(selection.paths);
    e.grid = plan.grid;
    std::optional<File> single;
    if (plan.layout != Layout::FilePerMember) single.emplace(selection.paths.front());
    report(progress, 0.0);
    const std::size_t count = plan.memberNames.size();
    for (std::size_t m = 0; m < count; ++m) {
        throwIfStopped(stop);
        Member member{plan.memberNames[m], FieldValues(plan.grid.pointCount())};
        readMember(single ? &*single : nullptr, selection, plan, m, member.values);
        e.members.push_back(std::move(member));
        report(progress, static_cast<double>(m + 1) / static_cast<double>(count));
    }
    return e;
}

}  // namespace ensil::data
