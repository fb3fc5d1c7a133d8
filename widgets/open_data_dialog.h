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
#include "engine/data_probe.h"

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QSpinBox;
class QLineEdit;
class QTreeWidget;

namespace ensil::ui {

class OpenDataDialog : public QDialog {
    Q_OBJECT
public:
    explicit OpenDataDialog(QStringList paths, QWidget* parent = nullptr);

    // Asks for a probe of the current choices (the first one when the dialog opens).
    void requestProbe();
    // Shows the answer to the latest request; answers to older requests are ignored.
    void showProbe(const engine::DataProbe& probe, int request);

    // The choices, ready for MainWindow::openFiles (a level range or region that does not parse
    // is left out; levelsError and regionError say why).
    [[nodiscard]] data::DataSelection selection() const;
    [[nodiscard]] bool isProbing() const { return m_probing; }
    [[nodiscard]] QString errorText() const;
    // Why the Levels text is not a level range; empty when it is one, or empty.
    [[nodiscard]] QString levelsError() const;
    // Why the Region text is not a region (LON0,LON1,LAT0,LAT1); empty when it is one, or empty.
    [[nodiscard]] QString regionError() const;
    [[nodiscard]] bool canAccept() const;
    [[nodiscard]] QTreeWidget* variableList() const { return m_variables; }
    [[nodiscard]] QComboBox* memberDimensionBox() const { return m_memberDimension; }
    [[nodiscard]] QSpinBox* timeIndexBox() const { return m_timeIndex; }
    [[nodiscard]] QLineEdit* levelsEdit() const { return m_levels; }
    [[nodiscard]] QLineEdit* regionEdit() const { return m_region; }

signals:
    // `request` numbers the requests, so that a late answer cannot overwrite a newer one.
    void probeRequested(const ensil::data::DataSelection& selection, int request);
    void probeShown();

private:
    void fillVariables(const engine::DataProbe& probe);
    void fillMemberDimensions(const engine::DataProbe& probe);
    void fillDetails(const engine::DataProbe& probe);
    void setProbing(bool probing);

    QStringList m_paths;
    QTreeWidget* m_variables;
    QComboBox* m_memberDimension;
    QSpinBox* m_timeIndex;
    QLineEdit* m_levels;  // the level range kept (data/level_range.h); empty: every level
    QLineEdit* m_region;  // the region kept (data/region.h); empty: the whole grid
    QLabel* m_details;
    QLabel* m_error;
    QDialogButtonBox* m_buttons;
    QString m_variable;  // the variable the last probe resolved to
    bool m_usableVariable = false;
    bool m_probing = false;
    int m_request = 0;
};

}  // namespace ensil::ui
