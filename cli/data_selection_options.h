// The data-selection options every command that reads files shares (info, preprocess, render,
// and the workbench itself): PATH..., --var, --member-dim, --time-index, --levels, --bbox. Main
// thread.
#pragma once

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <optional>

#include "data/ensemble_reader.h"

namespace ensil::cli {

class DataSelectionOptions {
public:
    DataSelectionOptions();
    void addTo(QCommandLineParser& parser) const;
    // Builds the selection from the parsed options and positional paths; on a bad value returns
    // nullopt and sets `error` to a message naming the option.
    std::optional<data::DataSelection> selection(const QCommandLineParser& parser,
                                                 QString& error) const;

private:
    QCommandLineOption m_variable;
    QCommandLineOption m_memberDim;
    QCommandLineOption m_timeIndex;
    QCommandLineOption m_levels;
    QCommandLineOption m_region;  // --bbox
};

}  // namespace ensil::cli
