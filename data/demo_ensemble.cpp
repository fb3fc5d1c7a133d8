#include "data/demo_ensemble.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "data/cf_conventions.h"
#include "data/ensemble_reader.h"
#include "data/error.h"

namespace ensil::data {
namespace {

constexpr double kLonMin = -80.0, kLonMax = 40.0;
constexpr double kLatMin = 25.0, kLatMax = 75.0;
constexpr double kPressureBottom = 1000.0, kPressureTop = 100.0;  // hPa
constexpr double kScaleHeightKm = 7.0;

// Uniform in [0, 1) from the engine's raw bits: identical on every standard library.
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * uniform(rng); }
// Approximately normal (Irwin-Hall with 4 terms), portable unlike std::normal_distribution.
double gaussian(std::mt19937_64& rng, double sigma) {
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) sum += uniform(rng);
    return (sum - 2.0) * std::sqrt(3.0) * sigma;
}
double smoothstep(double t) {
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// One jet stream: a tube of fast wind around a meandering core line.
struct Jet {
    double coreLat = 48.0;      // degrees north
    double meander = 5.0;       // meander amplitude, degrees
    double wavelength = 70.0;   // meander wavelength, degrees of longitude
    double phase = 0.0;         // degrees of longitude
    double halfWidth = 6.0;     // degrees of latitude
    double peak = 55.0;         // m/s at the core
    double coreHeightKm = 9.5;  // about 270 hPa
    double depthKm = 3.0;
    double lonStart = -1e9, lonEnd = 1e9, lonRamp = 10.0;  // where along longitude it exists
    double eastwardFade = 0.0;  // relative change of peak from west to east edge

    [[nodiscard]] double coreLatAt(double lon) const {
        return coreLat + meander * std::sin(2.0 * std::numbers::pi * (lon - phase) / wavelength);
    }
    [[nodiscard]] double slopeAt(double lon) const {  // d coreLat / d lon
        const double k = 2.0 * std::numbers::pi / wavelength;
        return meander * k * std::cos(k * (lon - phase));
    }
    [[nodiscard]] double envelope(double lon) const {
        const double fade = 1.0 + eastwardFade * (lon - kLonMin) / (kLonMax - kLonMin);
        return std::max(0.0, fade) * smoothstep((lon - lonStart) / lonRamp) *
               (1.0 - smoothstep((lon - lonEnd) / lonRamp));
    }
};

std::vector<Jet> regimeJets(DemoRegime regime) {
    Jet subtropical{.coreLat = 30.0,
                    .meander = 2.0,
                    .wavelength = 90.0,
                    .halfWidth = 4.0,
                    .peak = 42.0,
                    .coreHeightKm = 12.0,
                    .depthKm = 2.5};
    switch (regime) {
        case DemoRegime::Zonal:
            return {subtropical, Jet{}};
        case DemoRegime::Split:
            return {subtropical, Jet{.lonEnd = -15.0},
                    Jet{.coreLat = 58.0, .meander = 3.0, .peak = 48.0, .lonStart = -25.0},
                    Jet{.coreLat = 39.0, .meander = 3.0, .peak = 45.0, .lonStart = -25.0}};
        case DemoRegime::NorthFading:
            return {subtropical,
                    Jet{.coreLat = 56.0, .meander = 7.0, .peak = 62.0, .eastwardFade = -0.65}};
        case DemoRegime::Outlier:
            return {subtropical, Jet{.meander = 12.0, .wavelength = 45.0, .peak = 70.0},
                    Jet{.coreLat = 34.0,
                        .meander = 1.0,
                        .halfWidth = 4.0,
                        .peak = 78.0,
                        .coreHeightKm = 10.5,
                        .lonStart = -40.0,
                        .lonEnd = 10.0}};
    }
    return {};
}

void perturb(Jet& jet, std::mt19937_64& rng) {
    jet.coreLat += gaussian(rng, 1.5);
    jet.phase += uniform(rng, -12.0, 12.0);
    jet.peak *= 1.0 + uniform(rng, -0.12, 0.12);
    jet.halfWidth *= 1.0 + uniform(rng, -0.1, 0.1);
    jet.coreHeightKm += uniform(rng, -0.4, 0.4);
}

// Small-scale variability: a few plane waves, separable into a horizontal and a vertical part.
struct Wave {
    double kx, ky, kz, phase, amplitude;
};

struct MemberRecipe {
    std::vector<Jet> jets;
    std::vector<Wave> waves;
};

std::vector<DemoRegime> assignRegimes(std::size_t members, std::mt19937_64& rng) {
    std::vector<DemoRegime> regimes(members);
    for (std::size_t m = 0; m < members; ++m) {
        // 45 % zonal, 35 % split, 20 % north-fading: unequal clusters, as in real ensembles.
        const double r = uniform(rng);
        regimes[m] = r < 0.45   ? DemoRegime::Zonal
                     : r < 0.80 ? DemoRegime::Split
                                : DemoRegime::NorthFading;
    }
    if (members >= 4) regimes[static_cast<std::size_t>(rng() % members)] = DemoRegime::Outlier;
    return regimes;
}

MemberRecipe makeRecipe(DemoRegime regime, std::mt19937_64& rng) {
    MemberRecipe recipe{regimeJets(regime), {}};
    for (Jet& jet : recipe.jets) perturb(jet, rng);
    for (int w = 0; w < 4; ++w) {
        recipe.waves.push_back({uniform(rng, 0.05, 0.25), uniform(rng, 0.05, 0.3),
                                uniform(rng, 0.2, 0.6), uniform(rng, 0.0, 6.283),
                                uniform(rng, 0.8, 2.0)});
    }
    return recipe;
}

void fillMember(const MemberRecipe& recipe, const Grid& grid, const std::vector<double>& heightKm,
                FieldValues& out) {
    const std::size_t nx = grid.nx(), ny = grid.ny(), nz = grid.nz(), nxy = nx * ny;
    const std::size_t nj = recipe.jets.size(), nw = recipe.waves.size();
    // Horizontal parts: per jet the wind components at full strength; per wave sin and cos.
    std::vector<float> ju(nj * nxy), jv(nj * nxy), ws(nw * nxy), wc(nw * nxy);
    for (std::size_t j = 0; j < ny; ++j) {
        const double lat = grid.y().values[j];
        for (std::size_t i = 0; i < nx; ++i) {
            const double lon = grid.x().values[i];
            const std::size_t p = i + nx * j;
            for (std::size_t q = 0; q < nj; ++q) {
                const Jet& jet = recipe.jets[q];
                const double d = (lat - jet.coreLatAt(lon)) / jet.halfWidth;
                const double speed = jet.peak * jet.envelope(lon) * std::exp(-d * d);
                const double slope = jet.slopeAt(lon);
                const double norm = std::sqrt(1.0 + slope * slope);
                ju[q * nxy + p] = static_cast<float>(speed / norm);
                jv[q * nxy + p] = static_cast<float>(speed * slope / norm);
            }
            for (std::size_t q = 0; q < nw; ++q) {
                const Wave& w = recipe.waves[q];
                const double a = w.kx * lon + w.ky * lat + w.phase;
                ws[q * nxy + p] = static_cast<float>(w.amplitude * std::sin(a));
                wc[q * nxy + p] = static_cast<float>(w.amplitude * std::cos(a));
            }
        }
    }
    std::vector<float> jetProfile(nj), waveCos(nw), waveSin(nw);
    for (std::size_t k = 0; k < nz; ++k) {
        const double h = heightKm[k];
        for (std::size_t q = 0; q < nj; ++q) {
            const double d = (h - recipe.jets[q].coreHeightKm) / recipe.jets[q].depthKm;
            jetProfile[q] = static_cast<float>(std::exp(-d * d));
        }
        for (std::size_t q = 0; q < nw; ++q) {
            waveCos[q] = static_cast<float>(std::cos(recipe.waves[q].kz * h));
            waveSin[q] = static_cast<float>(std::sin(recipe.waves[q].kz * h));
        }
        // Westerly background that strengthens with height (thermal wind), capped aloft.
        const auto background = static_cast<float>(3.0 + 1.2 * std::min(h, 12.0));
        float* slab = out.data() + k * nxy;
        for (std::size_t p = 0; p < nxy; ++p) {
            float u = background, v = 0.0F, noise = 0.0F;
            for (std::size_t q = 0; q < nj; ++q) {
                u += ju[q * nxy + p] * jetProfile[q];
                v += jv[q * nxy + p] * jetProfile[q];
            }
            for (std::size_t q = 0; q < nw; ++q) {  // sin(a + b) = sin a cos b + cos a sin b
                noise += ws[q * nxy + p] * waveCos[q] + wc[q * nxy + p] * waveSin[q];
            }
            // Where jets overlap their speeds add up; saturate smoothly so the strongest cores
            // stay near the strongest observed jets (~110 m/s). 30 m/s changes by 0.01 %.
            const float speed = std::max(0.0F, std::sqrt(u * u + v * v) + noise);
            const float r = speed / 110.0F;
            slab[p] = speed / std::sqrt(std::sqrt(1.0F + r * r * r * r));
        }
    }
}

// out = (1 - w) out + w (the field of `recipe`): a member on its way to another regime.
void blendInto(const MemberRecipe& recipe, double w, const Grid& grid,
               const std::vector<double>& heightKm, FieldValues& out) {
    FieldValues other(grid.pointCount());
    fillMember(recipe, grid, heightKm, other);
    const auto a = static_cast<float>(1.0 - w), b = static_cast<float>(w);
    for (std::size_t p = 0; p < out.size(); ++p) out[p] = a * out[p] + b * other[p];
}

Axis pressureAxis(std::size_t nz) {
    Axis axis;
    axis.name = "plev";
    axis.units = "hPa";
    axis.standardName = "air_pressure";
    axis.positiveUp = false;
    axis.values.resize(nz);
    for (std::size_t k = 0; k < nz; ++k) {
        const double t = nz > 1 ? static_cast<double>(k) / static_cast<double>(nz - 1) : 0.0;
        const double p = kPressureBottom * std::pow(kPressureTop / kPressureBottom, t);
        axis.values[k] = std::round(p * 10.0) / 10.0;
    }
    return axis;
}

// How a member changes over the steps: the regime it turns into, with its own jets, and the
// fraction of the series at which it is half way there.
struct MemberChange {
    bool changes = false;
    DemoRegime to = DemoRegime::Zonal;
    MemberRecipe recipe;
    double halfWay = 0.5;
};

// About a third of the members (never the outlier) turn into another regime. Drawn from their
// own engine, so the recipes of step 0, and makeDemoEnsemble's ensemble, stay as they were.
std::vector<MemberChange> drawChanges(const std::vector<DemoRegime>& regimes,
                                      const std::vector<MemberRecipe>& recipes,
                                      std::uint64_t seed) {
    std::mt19937_64 rng(seed ^ 0x7469'6d65'7374'6570ULL);  // "timestep"
    std::vector<MemberChange> changes(regimes.size());
    constexpr std::array<DemoRegime, 3> kRegimes{DemoRegime::Zonal, DemoRegime::Split,
                                                 DemoRegime::NorthFading};
    for (std::size_t m = 0; m < regimes.size(); ++m) {
        MemberChange& c = changes[m];
        const double draw = uniform(rng);
        const auto offset = static_cast<std::size_t>(1 + rng() % 2);
        c.halfWay = uniform(rng, 0.15, 0.85);
        if (regimes[m] == DemoRegime::Outlier || draw >= 0.35) continue;
        const auto from = static_cast<std::size_t>(
            std::find(kRegimes.begin(), kRegimes.end(), regimes[m]) - kRegimes.begin());
        c.changes = true;
        c.to = kRegimes[(from + offset) % kRegimes.size()];
        c.recipe = makeRecipe(c.to, rng);
        c.recipe.waves = recipes[m].waves;  // the same small-scale noise: only the flow changes
    }
    return changes;
}

// The drift every jet makes by fraction `t` of the series: 30 degrees east, 3 degrees north.
MemberRecipe drifted(MemberRecipe recipe, double t) {
    for (Jet& jet : recipe.jets) {
        jet.phase += 30.0 * t;
        jet.coreLat += 3.0 * t;
        jet.lonStart += 30.0 * t;
        jet.lonEnd += 30.0 * t;
    }
    return recipe;
}

}  // namespace

DemoEnsemble makeDemoEnsemble(const DemoEnsembleParams& params, const std::stop_token& stop,
                              const Progress& progress) {
    return makeDemoEnsembleAt(params, 0, 1, stop, progress);
}

DemoEnsemble makeDemoEnsembleAt(const DemoEnsembleParams& params, std::size_t step,
                                std::size_t steps, const std::stop_token& stop,
                                const Progress& progress) {
    if (step >= steps) {
        throw Error(ErrorKind::InvalidArgument, "the demo's step " + std::to_string(step) +
                                                    " is past its " + std::to_string(steps) +
                                                    " steps");
    }
    if (params.members < 1) {
        throw Error(ErrorKind::InvalidArgument, "the demo ensemble needs at least 1 member");
    }
    if (params.nx < 2 || params.ny < 2 || params.nz < 2) {
        throw Error(ErrorKind::InvalidArgument,
                    "the demo grid needs at least 2 points along every axis");
    }
    checkMemoryFor(params.members * params.nx * params.ny * params.nz * sizeof(float),
                   "the demo ensemble (" + std::to_string(params.members) + " members of " +
                       std::to_string(params.nx) + " x " + std::to_string(params.ny) + " x " +
                       std::to_string(params.nz) + " points)");
    Axis lon = makeUniformAxis("lon", "degrees_east", kLonMin, kLonMax, params.nx);
    lon.standardName = "longitude";
    Axis lat = makeUniformAxis("lat", "degrees_north", kLatMin, kLatMax, params.ny);
    lat.standardName = "latitude";

    DemoEnsemble result;
    Ensemble& ens = result.ensemble;
    ens.variable = "wind_speed";
    ens.longName = "Wind speed (ensil demo jet streams)";
    ens.units = "m s-1";
    ens.memberDimension = "number";
    ens.source = "demo";
    ens.grid = Grid(std::move(lon), std::move(lat), pressureAxis(params.nz));
    if (steps > 1) {
        ens.timeSteps.dimension = "time";
        for (std::size_t i = 0; i < steps; ++i) {
            ens.timeSteps.labels.push_back(
                formatCfTime(kDemoHoursPerStep * static_cast<double>(i), kDemoTimeUnits)
                    .value_or(std::to_string(i)));
        }
        ens.fixedDimensions.push_back("time = " + std::to_string(step) + " of " +
                                      std::to_string(steps) + " (" + ens.timeSteps.labels[step] +
                                      ")");
    }

    std::vector<double> heightKm(params.nz);
    for (std::size_t k = 0; k < params.nz; ++k) {
        heightKm[k] = -kScaleHeightKm * std::log(ens.grid.z().values[k] / kPressureBottom);
    }

    // Recipes are drawn serially so the result does not depend on the number of threads.
    std::mt19937_64 rng(params.seed);
    result.regimes = assignRegimes(params.members, rng);
    std::vector<MemberRecipe> recipes;
    recipes.reserve(params.members);
    for (DemoRegime regime : result.regimes) recipes.push_back(makeRecipe(regime, rng));
    const double along =  // the fraction of the series at this step
        steps > 1 ? static_cast<double>(step) / static_cast<double>(steps - 1) : 0.0;
    std::vector<MemberChange> changes;
    std::vector<double> weights(params.members, 0.0);  // of the regime turned into
    if (steps > 1) {
        changes = drawChanges(result.regimes, recipes, params.seed);
        for (std::size_t m = 0; m < params.members; ++m) {
            if (!changes[m].changes) continue;
            weights[m] = smoothstep((along - changes[m].halfWay) / 0.3 + 0.5);
            changes[m].recipe = drifted(std::move(changes[m].recipe), along);
            if (weights[m] >= 0.5) result.regimes[m] = changes[m].to;
        }
        for (MemberRecipe& recipe : recipes) recipe = drifted(std::move(recipe), along);
    }

    ens.members.resize(params.members);
    for (std::size_t m = 0; m < params.members; ++m) {
        ens.members[m].name = "member " + std::to_string(m + 1);
        ens.members[m].values.resize(ens.grid.pointCount());
    }
    const std::size_t threads =
        std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, params.members);
    std::atomic<std::size_t> done{0};
    {
        std::vector<std::jthread> workers;
        for (std::size_t t = 0; t < threads; ++t) {
            workers.emplace_back([&, t] {
                for (std::size_t m = t; m < params.members && !stop.stop_requested();
                     m += threads) {
                    fillMember(recipes[m], ens.grid, heightKm, ens.members[m].values);
                    if (weights[m] > 0.0)
                        blendInto(changes[m].recipe, weights[m], ens.grid, heightKm,
                                  ens.members[m].values);
                    const std::size_t finished = ++done;
                    // One thread reports, so the callback is never called concurrently.
                    if (t == 0) {
                        report(progress,
                               static_cast<double>(finished) / static_cast<double>(params.members));
                    }
                }
            });
        }
    }
    throwIfStopped(stop);
    return result;
}

}  // namespace ensil::data
