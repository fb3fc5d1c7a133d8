// ensil_settings_reference: prints the settings reference of the user's guide (docs/settings.md)
// from the setting table, so the page is regenerated, never edited by hand:
//   build/ci/packaging/ensil_settings_reference > docs/settings.md
#include <iostream>

#include "session/setting_reference.h"

int main() {
    std::cout << ensil::session::settingReferenceMarkdown();
    return 0;
}
