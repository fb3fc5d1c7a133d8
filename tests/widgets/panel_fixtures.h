// Shared fixtures for the panel tests: members on a line (their distance is how far apart they
// sit, so the clusters are known), and a check that item models obey Qt's model contract.
#pragma once

#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QMouseEvent>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <cmath>
#include <vector>

#include "preprocessing/clustering.h"
#include "widgets/member_selection.h"

namespace ensil::test {

// Six members in two groups, interleaved so the dendrogram order differs from the index
// order: {0, 2, 4} near 0 and {1, 3, 5} near 10.
inline const std::vector<double> kTwoGroups{0.0, 10.0, 0.5, 10.7, 1.5, 12.0};

inline prep::MergeTree treeOnALine(const std::vector<double>& positions,
                                   prep::Linkage linkage = prep::Linkage::Average) {
    prep::DistanceMatrix d;
    d.size = positions.size();
    d.values.resize(d.size * d.size);
    for (std::size_t i = 0; i < d.size; ++i)
        for (std::size_t j = 0; j < d.size; ++j)
            d.values[i * d.size + j] = std::abs(positions[i] - positions[j]);
    return prep::clusterMembers(d, linkage);
}

// Names "m0", "m1", ...; distance to the mean = position; outlyingness = 2 * position, except
// member 2's, which is unknown (NaN).
inline ui::MemberFigures figuresOnALine(const std::vector<double>& positions) {
    ui::MemberFigures f;
    for (std::size_t m = 0; m < positions.size(); ++m) {
        f.names << QStringLiteral("m%1").arg(m);
        f.distanceToMean.push_back(positions[m]);
        f.meanOutlyingness.push_back(m == 2 ? std::nan("") : 2.0 * positions[m]);
    }
    return f;
}

inline void loadTwoGroups(ui::MemberSelection& selection, int clusters = 2) {
    selection.setMembers(figuresOnALine(kTwoGroups));
    selection.setTree(treeOnALine(kTwoGroups));
    selection.setClusterCount(clusters);
}

// A mouse move with no button held, delivered straight to the widget. QTest::mouseMove moves
// the display's real pointer instead, which test processes running side by side on one display
// fight over.
inline void moveMouse(QWidget* widget, QPoint pos) {
    QMouseEvent move(QEvent::MouseMove, QPointF(pos), QPointF(widget->mapToGlobal(pos)),
                     Qt::NoButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(widget, &move);
}

// Collects QAbstractItemModelTester's complaints (it reports them as warnings starting with
// "FAIL!") while it lives, so a test can assert there were none.
class ModelContractCheck {
public:
    explicit ModelContractCheck(QAbstractItemModel* model) {
        failures().clear();
        m_previous = qInstallMessageHandler(&ModelContractCheck::handle);
        m_tester = std::make_unique<QAbstractItemModelTester>(
            model, QAbstractItemModelTester::FailureReportingMode::Warning);
    }
    ~ModelContractCheck() {
        m_tester.reset();
        qInstallMessageHandler(m_previous);
    }
    ModelContractCheck(const ModelContractCheck&) = delete;
    ModelContractCheck& operator=(const ModelContractCheck&) = delete;

    [[nodiscard]] static QStringList& failures() {
        static QStringList list;
        return list;
    }

private:
    static void handle(QtMsgType type, const QMessageLogContext&, const QString& message) {
        if (type != QtDebugMsg && message.contains(QLatin1String("FAIL!"))) failures() << message;
    }
    QtMessageHandler m_previous = nullptr;
    std::unique_ptr<QAbstractItemModelTester> m_tester;
};

}  // namespace ensil::test
