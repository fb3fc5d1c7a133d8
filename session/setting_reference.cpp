#include "session/setting_reference.h"

#include <sstream>
#include <string_view>

#include "session/setting_table.h"

namespace ensil::session {
namespace {

// A table cell: no line breaks or bars, which would end the cell.
std::string cell(std::string_view text) {
    std::string out;
    for (const char c : text) {
        if (c == '|') {
            out += "\\|";
        } else if (c == '\n') {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

std::string code(std::string_view text) {
    return text.empty() ? "" : "`" + std::string(text) + "`";
}

}  // namespace

std::string settingReferenceMarkdown() {
    std::ostringstream out;
    out << "# Settings\n\n"
           "Every setting of a picture and a session, as the setting table in the source defines "
           "it (this page is\nwritten from that table by `ensil_settings_reference`; a test fails "
           "when it differs). The same\nsetting goes by its **option** on the command line "
           "(`ensil render --OPTION VALUE`, a flag as `--OPTION` or\n`--no-OPTION`; `ensil "
           "section` "
           "takes the sections' and the vertical axis's), by its **project key** in a `.ensil` "
           "project file, and by\nits "
           "**id** in Python (`ensil.render(ens, ID=VALUE)`, `Session.settings`). The Rendering "
           "panel shows\nit under its name, with the same range; a value outside it is refused "
           "everywhere with the same\nmessage.\n\n"
           "| setting | id | option | project key | values | default | what it does |\n"
           "|---|---|---|---|---|---|---|\n";
    for (const Setting& s : settingTable()) {
        std::string defaultText = s.format(s.defaultValue());
        if (!s.unit.empty() && (s.kind == SettingKind::Number || s.kind == SettingKind::Integer)) {
            defaultText += " " + std::string(s.unit);
        }
        out << "| " << cell(s.label) << " | " << code(s.id) << " | "
            << (s.option.empty()              ? std::string("(none)")
                : s.kind == SettingKind::Flag ? code("--" + std::string(s.option)) + ", " +
                                                    code("--no-" + std::string(s.option))
                                              : code("--" + std::string(s.option)))
            << " | " << (s.projectKey.empty() ? std::string("(not saved)") : code(s.projectKey))
            << " | " << cell(s.allowed()) << " | " << cell(defaultText) << " | " << cell(s.help)
            << " |\n";
    }
    return out.str();
}

}  // namespace ensil::session
