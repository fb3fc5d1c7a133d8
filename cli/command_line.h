// The command-line front end of the `ensil` executable. Subcommands (generate, info, preprocess,
// render) run without a display; anything else asks for the workbench. Pure dispatch: output
// goes to the given streams so tests can read it. Main thread only.
#pragma once

#include <QStringList>
#include <QTextStream>
#include <optional>

#include "data/ensemble_reader.h"

namespace ensil::cli {

// What the workbench should open: no paths means the built-in demo.
struct WorkbenchRequest {
    data::DataSelection selection;
    std::size_t memoryLimit = 0;  // --memory-limit; 0: engine::defaultMemoryLimit()
};

struct CommandLineOutcome {
    int exitCode = 0;
    std::optional<WorkbenchRequest> workbench;  // set when the GUI should start
};

// True when args (including the program name) name a subcommand or --help/--version, i.e. the
// run needs no display and no QApplication.
bool isHeadlessInvocation(const QStringList& args);

// What `ensil --version` prints: "ensil X.Y.Z", then the libraries it runs with (Qt and the
// readers', as loaded, not as compiled against) and the compiler that built it.
QString versionText();

CommandLineOutcome runCommandLine(const QStringList& args, QTextStream& out, QTextStream& err);

}  // namespace ensil::cli
