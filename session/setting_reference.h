// The reference of every setting for the user's guide (docs/settings.md), written from the
// setting table itself (session/setting_table.h): what it does, the values it takes, its default,
// and the names it goes by on the command line, in a project file and in Python, so the guide
// cannot disagree with what ensil accepts. packaging/settings_reference.cpp prints it; a test
// fails when docs/settings.md is not what it prints. Any thread.
#pragma once

#include <string>

namespace ensil::session {

// The whole page, Markdown, ending in a newline.
std::string settingReferenceMarkdown();

}  // namespace ensil::session
