#include "cli/subcommand.h"

#include "data/region.h"

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

int dataFailureStatus(const std::exception& e) {
    return dynamic_cast<const data::RegionOutsideGrid*>(&e) != nullptr ? 2 : 1;
}

const session::SettingOptions& clusterOptions() {
    static const session::SettingOptions options{"clusters", "linkage"};
    return options;
}

}  // namespace ensil::cli
