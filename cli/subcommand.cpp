#include "cli/subcommand.h"

namespace ensil::cli {

std::optional<int> parseSubcommand(QCommandLineParser& parser, const QStringList& args,
                                   const QString& name, QTextStream& out, QTextStream& err) {
    if (!parser.parse(args)) {
        err << "ensil " << name << ": " << parser.errorText() << "\nRun 'ensil " << name
            << " --help' for its options.\n";
        return 2;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << parser.helpText().replace(QStringLiteral("[options]"),
                                         name + QStringLiteral(" [options]"));
        return 0;
    }
    return std::nullopt;
}

}  // namespace ensil::cli
