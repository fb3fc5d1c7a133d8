// Compares a rendered image with a baseline PNG in tests/baselines/ under a tolerance, the way
// F3D's tests do. On a mismatch, or when the baseline is missing, writes NAME.actual.png and
// NAME.diff.png (differences amplified, red where beyond tolerance) into the test output folder
// and reports failure. Set ENSIL_UPDATE_BASELINES=1 to write the actual image as the baseline.
#pragma once

#include <QImage>
#include <QString>

namespace ensil::test {

struct ImageTolerance {
    // A pixel differs when any channel differs by more than this (0..255). llvmpipe is
    // deterministic on one machine; this absorbs rounding differences between Mesa builds.
    int channel = 24;
    // The comparison fails when more than this fraction of pixels differ: a moved edge or a
    // missing object changes far more, an anti-aliasing change on a few edge pixels less.
    double fraction = 0.005;
};

struct ImageComparison {
    bool passed = false;
    double differingFraction = 1.0;
    QString message;  // what happened and where the actual and diff images are
};

ImageComparison compareWithBaseline(const QImage& actual, const QString& name,
                                    ImageTolerance tolerance = {});

// Fraction of pixels that differ beyond tolerance.channel; images of different size give 1.
double differingFraction(const QImage& a, const QImage& b, int channelTolerance,
                         QImage* diff = nullptr);

// Where tests write their images (created on demand).
QString testOutputDir();

}  // namespace ensil::test
