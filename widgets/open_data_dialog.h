// The dialog between choosing files and reading them: it lists the variables the files hold
// (name, dimensions, units, long name; unusable ones greyed with the reason), lets the user pick
// one, override the detected member dimension and choose the time index, and shows what the
// readers say in plain words (OK stays disabled while the files cannot be read as chosen).
// It knows no readers: every change of choice emits probeRequested, and whoever owns the readers
// answers with showProbe() (from a worker thread's result, so the dialog never blocks).
// GUI thread only.
#pragma once

#include <QDialog>
#include <QStringList>
#include <vector>

#include "data/ensemble_reader.h"

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QSpinBox;
class QTreeWidget;

namespace ensil::ui {

struct ProbedVariable {
    QString name;
    QString dimensions;  // "number=10, time=4, plev=2, lat=61, lon=120"
    QString units;
    QString longName;
    bool usable = false;
    QString whyNotUsable;  // set when !usable
};

// What the files hold under the current choices, as the headers say.
struct DataProbe {
    QString format;  // "NetCDF-4", "VTK legacy", ...
    std::vector<ProbedVariable> variables;
    QString variable;                    // the variable the choices resolve to
    QStringList memberDimensionChoices;  // dimensions that could hold the members
    QString memberDimension;             // the one in use; empty: one member per file
    QString memberDimensionReason;       // "standard_name = realization", "chosen by you"
    int members = 0;
    int timeSteps = 0;            // indices along the fixed dimensions; 0 when none
    QStringList fixedDimensions;  // "time = 0 of 4 (2017-01-01T00:00)"
    QString grid;                 // "120 x 61 x 2"
    QString size;                 // "21 MiB of values", and how they open; empty: not said
    QString error;                // plain words; non-empty: the files cannot be read so
};

class OpenDataDialog : public QDialog {
    Q_OBJECT
public:
    explicit OpenDataDialog(QStringList paths, QWidget* parent = nullptr);

    // Asks for a probe of the current choices (the first one when the dialog opens).
    void requestProbe();
    // Shows the answer to the latest request; answers to older requests are ignored.
    void showProbe(const DataProbe& probe, int request);

    // The choices, ready for MainWindow::openFiles.
    [[nodiscard]] data::DataSelection selection() const;
    [[nodiscard]] bool isProbing() const { return m_probing; }
    [[nodiscard]] QString errorText() const;
    [[nodiscard]] bool canAccept() const;
    [[nodiscard]] QTreeWidget* variableList() const { return m_variables; }
    [[nodiscard]] QComboBox* memberDimensionBox() const { return m_memberDimension; }
    [[nodiscard]] QSpinBox* timeIndexBox() const { return m_timeIndex; }

signals:
    // `request` numbers the requests, so that a late answer cannot overwrite a newer one.
    void probeRequested(const ensil::data::DataSelection& selection, int request);
    void probeShown();

private:
    void fillVariables(const DataProbe& probe);
    void fillMemberDimensions(const DataProbe& probe);
    void fillDetails(const DataProbe& probe);
    void setProbing(bool probing);

    QStringList m_paths;
    QTreeWidget* m_variables;
    QComboBox* m_memberDimension;
    QSpinBox* m_timeIndex;
    QLabel* m_details;
    QLabel* m_error;
    QDialogButtonBox* m_buttons;
    QString m_variable;  // the variable the last probe resolved to
    bool m_usableVariable = false;
    bool m_probing = false;
    int m_request = 0;
};

}  // namespace ensil::ui
