// Fuzzes the project parser (session/project_file.h, projectFromJson) on raw bytes. A
// project file is user-edited, shared and double-clicked, so any text must be either accepted
// whole or refused with ProjectError naming the line or field; any other exception type or a
// crash is a finding. A project it accepts must also survive saving: projectToJson of what was
// read must parse again (a project that cannot be reopened after saving is a bug of the writer
// or the validator; the text need not come back byte for byte, as the plane's normal is
// normalised on reading, which may move it by an ulp). It found at once that a setting at a
// bound that is not a float (cutting_plane.thickness 0.1, saved as 0.10000000149) was then
// refused; Setting::problemWith now accepts a bound's float.
#include <QByteArray>
#include <QDir>
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "session/project_file.h"
#include "tests/fuzz/fuzz_support.h"

// NOLINTNEXTLINE(readability-identifier-naming): the name libFuzzer calls
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ensil::session;
    // Relative data paths resolve against this folder (only whether files exist there is asked).
    static const QDir projectDir(QString::fromStdString(ensil::fuzz::temporaryFolder()));
    const QByteArray json(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    SessionState state;
    try {
        state = projectFromJson(json, projectDir);
    } catch (const ProjectError& e) {
        ensil::fuzz::refused(e);
        return 0;
    } catch (const std::exception& e) {
        ensil::fuzz::unexpected(e);
    }
    try {
        const QByteArray saved = projectToJson(state, projectDir);
        (void)projectFromJson(saved, projectDir);
    } catch (const ProjectError& e) {
        std::fprintf(stderr, "reopening the saved project failed: %s\n", e.what());
        ensil::fuzz::unexpected("an accepted project could not be reopened after saving");
    } catch (const std::exception& e) {
        ensil::fuzz::unexpected(e);
    }
    return 0;
}
