#include "tests/support/image_compare.h"

#include <QDir>
#include <algorithm>
#include <cstdlib>

namespace ensil::test {

QString testOutputDir() {
    const QString dir = QStringLiteral(ENSIL_TEST_OUTPUT_DIR);
    QDir().mkpath(dir);
    return dir;
}

double differingFraction(const QImage& a, const QImage& b, int channelTolerance, QImage* diff) {
    if (a.size() != b.size() || a.isNull()) return 1.0;
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888);
    const QImage y = b.convertToFormat(QImage::Format_RGBA8888);
    if (diff != nullptr) *diff = QImage(x.size(), QImage::Format_RGBA8888);
    qint64 differing = 0;
    for (int row = 0; row < x.height(); ++row) {
        const uchar* px = x.constScanLine(row);
        const uchar* py = y.constScanLine(row);
        for (int col = 0; col < x.width(); ++col) {
            int worst = 0;
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs(px[4 * col + c] - py[4 * col + c]));
            const bool beyond = worst > channelTolerance;
            differing += beyond ? 1 : 0;
            if (diff != nullptr) {
                const int amplified = std::min(255, worst * 8);
                diff->setPixelColor(
                    col, row, beyond ? QColor(255, 0, 0) : QColor(amplified, amplified, amplified));
            }
        }
    }
    return static_cast<double>(differing) / (static_cast<double>(x.width()) * x.height());
}

ImageComparison compareWithBaseline(const QImage& actual, const QString& name,
                                    ImageTolerance tolerance) {
    ImageComparison result;
    const QString baselinePath = QStringLiteral(ENSIL_BASELINE_DIR "/") + name + ".png";
    const QString actualPath = testOutputDir() + QLatin1Char('/') + name + ".actual.png";
    const QString diffPath = testOutputDir() + QLatin1Char('/') + name + ".diff.png";
    if (qEnvironmentVariableIntValue("ENSIL_UPDATE_BASELINES") == 1) {
        actual.save(baselinePath);
        result.message = QStringLiteral("baseline written: ") + baselinePath;
        result.passed = false;  // never pass silently while updating baselines
        return result;
    }
    const QImage baseline(baselinePath);
    if (baseline.isNull()) {
        actual.save(actualPath);
        result.message = QStringLiteral(
                             "no baseline %1; the actual image is %2 (inspect it, "
                             "then run with ENSIL_UPDATE_BASELINES=1 to adopt it)")
                             .arg(baselinePath, actualPath);
        return result;
    }
    QImage diff;
    result.differingFraction = differingFraction(actual, baseline, tolerance.channel, &diff);
    result.passed = result.differingFraction <= tolerance.fraction;
    if (!result.passed) {
        actual.save(actualPath);
        if (!diff.isNull()) diff.save(diffPath);
        result.message =
            QStringLiteral("%1: %2 % of pixels differ (allowed %3 %); actual %4, diff %5")
                .arg(name)
                .arg(100.0 * result.differingFraction, 0, 'f', 3)
                .arg(100.0 * tolerance.fraction, 0, 'f', 3)
                .arg(actualPath, diffPath);
    }
    return result;
}

}  // namespace ensil::test
