// Shared fixtures for the panel tests: the members on a line of the selection's tests
// (tests/workbench/selection_fixtures.h), a mouse move, and a check that item models obey Qt's
// model contract.
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

#include "tests/workbench/selection_fixtures.h"

namespace ensil::test {

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
