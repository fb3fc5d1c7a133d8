#include "widgets/isovalue_control.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLineEdit>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QWheelEvent>
#include <cmath>

#include "widgets/histogram_strip.h"

using namespace ensil::ui;

namespace {
constexpr double kMin = -3.7;
constexpr double kMax = 83.456;

// Pixels in column x that are not the strip's background, counted from the bottom up.
int barHeight(const QImage& image, int x, const QColor& background) {
    int h = 0;
    for (int y = image.height() - 1; y >= 0; --y) {
        if (image.pixelColor(x, y) == background) break;
        ++h;
    }
    return h;
}
}  // namespace

TEST(IsovalueControl, SliderTicksMapLinearlyAndExactlyAtTheEnds) {
    IsovalueControl control;
    control.setRange(kMin, kMax, 10.0, QStringLiteral("m s-1"));
    EXPECT_EQ(control.valueAtSliderPosition(0), kMin);
    EXPECT_EQ(control.valueAtSliderPosition(IsovalueControl::kSliderSteps), kMax);
    EXPECT_EQ(control.sliderPositionOf(kMin), 0);
    EXPECT_EQ(control.sliderPositionOf(kMax), IsovalueControl::kSliderSteps);
    EXPECT_DOUBLE_EQ(control.valueAtSliderPosition(IsovalueControl::kSliderSteps / 4),
                     kMin + 0.25 * (kMax - kMin));
    for (int p = 0; p <= IsovalueControl::kSliderSteps; ++p) {
        ASSERT_EQ(control.sliderPositionOf(control.valueAtSliderPosition(p)), p) << p;
    }
    // Values outside the range stay on the slider.
    EXPECT_EQ(control.sliderPositionOf(kMin - 100.0), 0);
    EXPECT_EQ(control.sliderPositionOf(kMax + 100.0), IsovalueControl::kSliderSteps);

    // The spin box gets the units and decimals for a thousandth of the range (0.087 -> 2).
    EXPECT_EQ(control.spinBox()->suffix(), QStringLiteral(" m s-1"));
    EXPECT_EQ(control.spinBox()->decimals(), 2);
    EXPECT_EQ(control.slider()->value(), control.sliderPositionOf(10.0));
    EXPECT_DOUBLE_EQ(control.value(), 10.0);
}

TEST(IsovalueControl, DrawsTallerBarsWhereCountsAreHigherAndMarksTheValue) {
    IsovalueControl control;
    control.resize(480, 60);
    control.setRange(0.0, 4.0, 3.5, QString());
    control.setHistogram({1, 100000, 30, 0});
    control.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&control));
    control.grab().save(QStringLiteral(ENSIL_TEST_OUTPUT_DIR "/isovalue_control.png"));  // artifact
    HistogramStrip* strip = control.histogram();
    const QImage image = strip->grab().toImage();
    ASSERT_GT(image.width(), 40);
    const QColor background = strip->palette().color(QPalette::Base);
    const int binWidth = image.width() / 4;
    const int one = barHeight(image, binWidth / 2, background);
    const int many = barHeight(image, binWidth + binWidth / 2, background);
    const int some = barHeight(image, 2 * binWidth + binWidth / 2, background);
    EXPECT_GT(many, some);
    EXPECT_GT(some, one);
    EXPECT_GT(one, 0) << "a single value must stay visible on the log scale";
    EXPECT_EQ(many, image.height()) << "the fullest bin fills the strip";
    // Log scale: 30 values reach log(31)/log(100001) of the height, far more than linear would.
    EXPECT_NEAR(some, std::log1p(30.0) / std::log1p(100000.0) * image.height(), 1.5);

    // The marker at 3.5 lies in the empty last bin, where nothing else is drawn.
    const int markerColumn = strip->columnOf(3.5);
    EXPECT_EQ(barHeight(image, markerColumn, background), image.height());
    EXPECT_EQ(barHeight(image, markerColumn + 5, background), 0);
    EXPECT_EQ(barHeight(image, markerColumn - 5, background), 0);
}

TEST(IsovalueControl, DraggingTheSliderShowsValuesAndCommitsOnceOnRelease) {
    IsovalueControl control;
    control.setRange(kMin, kMax, 10.0, QString());
    QSignalSpy committed(&control, &IsovalueControl::isovalueChanged);
    QSlider* slider = control.slider();
    slider->setSliderDown(true);
    for (int p = 100; p <= 700; p += 50) slider->setSliderPosition(p);
    EXPECT_EQ(committed.count(), 0) << "no commit while dragging";
    EXPECT_NEAR(control.spinBox()->value(), control.valueAtSliderPosition(700), 0.005)
        << "the spin box follows the drag";
    EXPECT_NEAR(control.histogram()->marker(), control.valueAtSliderPosition(700), 1e-9);
    slider->setSliderDown(false);  // emits sliderReleased, as a mouse release does
    ASSERT_EQ(committed.count(), 1);
    EXPECT_NEAR(committed.front().front().toDouble(), control.valueAtSliderPosition(700), 0.005);

    // Dragged to the very end, the value is the maximum (as the spin box rounds it).
    slider->setSliderDown(true);
    slider->setSliderPosition(IsovalueControl::kSliderSteps);
    slider->setSliderDown(false);
    ASSERT_EQ(committed.count(), 2);
    EXPECT_NEAR(committed.back().front().toDouble(), kMax, 0.005);
}

TEST(IsovalueControl, ADragScrubsEveryValueUnderThePointerThenEndsAfterItsCommit) {
    IsovalueControl control;
    control.setRange(kMin, kMax, 10.0, QString());
    QStringList order;  // the order the signals came in
    QList<double> scrubbed;
    QObject::connect(&control, &IsovalueControl::isovalueScrubbed, [&](double v) {
        scrubbed << v;
        order << QStringLiteral("scrub");
    });
    QObject::connect(&control, &IsovalueControl::isovalueChanged,
                     [&] { order << QStringLiteral("commit"); });
    QObject::connect(&control, &IsovalueControl::scrubEnded,
                     [&] { order << QStringLiteral("end"); });
    QSlider* slider = control.slider();
    slider->setSliderDown(true);
    for (int p = 100; p <= 400; p += 100) slider->setSliderPosition(p);
    ASSERT_EQ(scrubbed.size(), 4);
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(scrubbed[i], control.valueAtSliderPosition(100 * (i + 1)), 0.005);
    }
    slider->setSliderDown(false);
    // The session starts the released value's full build before it hears the scrub is over.
    EXPECT_EQ(order.mid(4), (QStringList{QStringLiteral("commit"), QStringLiteral("end")}));

    // A step by key is no scrub.
    order.clear();
    slider->triggerAction(QAbstractSlider::SliderSingleStepAdd);
    EXPECT_EQ(order, QStringList{QStringLiteral("commit")});
}

TEST(IsovalueControl, TurningTheWheelScrubsAndCommitsOnceWhenItPauses) {
    IsovalueControl control;
    control.setRange(0.0, 100.0, 50.0, QString());
    control.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&control));
    QSignalSpy scrubbed(&control, &IsovalueControl::isovalueScrubbed);
    QSignalSpy committed(&control, &IsovalueControl::isovalueChanged);
    QSignalSpy ended(&control, &IsovalueControl::scrubEnded);
    QDoubleSpinBox* spin = control.spinBox();
    const QPoint centre = spin->rect().center();
    for (int turn = 0; turn < 5; ++turn) {
        QWheelEvent wheel(centre, spin->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(spin, &wheel);
    }
    EXPECT_EQ(scrubbed.count(), 5) << "each wheel step previews";
    EXPECT_EQ(committed.count(), 0) << "no rebuild per wheel step";
    ASSERT_TRUE(ended.wait(5000));
    ASSERT_EQ(committed.count(), 1);
    EXPECT_NEAR(committed.front().front().toDouble(), 55.0, 1e-9) << "five steps of 1 % of 100";
}

TEST(IsovalueControl, DraggingOnTheHistogramCommitsOnceOnRelease) {
    IsovalueControl control;
    control.resize(480, 60);
    control.setRange(0.0, 100.0, 50.0, QString());
    control.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&control));
    QSignalSpy committed(&control, &IsovalueControl::isovalueChanged);
    HistogramStrip* strip = control.histogram();
    const int y = strip->height() / 2;
    QTest::mousePress(strip, Qt::LeftButton, {}, QPoint(10, y));
    for (int x = 20; x <= 200; x += 10) QTest::mouseMove(strip, QPoint(x, y));
    EXPECT_EQ(committed.count(), 0);
    EXPECT_NEAR(control.value(), strip->valueAt(200), 0.1);
    QTest::mouseRelease(strip, Qt::LeftButton, {}, QPoint(220, y));
    ASSERT_EQ(committed.count(), 1);
    EXPECT_NEAR(committed.front().front().toDouble(), strip->valueAt(220), 0.1);
    EXPECT_EQ(control.slider()->value(), control.sliderPositionOf(control.value()));
}

TEST(IsovalueControl, TypingAValueCommitsOnceOnEnterAndNotPerKeystroke) {
    IsovalueControl control;
    control.setRange(0.0, 100.0, 50.0, QStringLiteral("K"));
    control.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&control));
    QSignalSpy committed(&control, &IsovalueControl::isovalueChanged);
    QDoubleSpinBox* spin = control.spinBox();
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("42.5"));
    EXPECT_EQ(committed.count(), 0);
    QTest::keyClick(spin, Qt::Key_Return);  // valueChanged and editingFinished: one commit
    ASSERT_EQ(committed.count(), 1);
    EXPECT_DOUBLE_EQ(committed.front().front().toDouble(), 42.5);
    EXPECT_EQ(control.slider()->value(), control.sliderPositionOf(42.5));
    QTest::keyClick(spin, Qt::Key_Return);  // the same value again is no new commit
    EXPECT_EQ(committed.count(), 1);
}

TEST(IsovalueControl, PageUpAndPageDownStepATenthOfTheRange) {
    IsovalueControl control;
    control.setRange(0.0, 200.0, 50.0, QString());
    control.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&control));
    QSignalSpy committed(&control, &IsovalueControl::isovalueChanged);
    QTest::keyClick(control.slider(), Qt::Key_PageUp);
    ASSERT_EQ(committed.count(), 1);
    EXPECT_DOUBLE_EQ(control.value(), 70.0);
    QTest::keyClick(control.spinBox(), Qt::Key_PageDown);
    ASSERT_EQ(committed.count(), 2);
    EXPECT_DOUBLE_EQ(control.value(), 50.0);
    EXPECT_EQ(control.slider()->value(), control.sliderPositionOf(50.0));
}

TEST(IsovalueControl, SettingTheRangeOrValueInCodeEmitsNothing) {
    IsovalueControl control;
    EXPECT_FALSE(control.isEnabled()) << "nothing to choose before a range is known";
    QSignalSpy committed(&control, &IsovalueControl::isovalueChanged);
    control.setRange(1.0, 2.0, 1.5, QString());
    control.setValue(1.75);
    EXPECT_TRUE(control.isEnabled());
    EXPECT_EQ(committed.count(), 0);
    EXPECT_DOUBLE_EQ(control.value(), 1.75);
}
