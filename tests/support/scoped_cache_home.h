// Points XDG_CACHE_HOME (the mesh cache, and Mesa's shader cache) at a fresh temporary folder
// for one test and puts the previous value back afterwards, so later tests do not write into a
// folder that is gone.
#pragma once

#include <QByteArray>
#include <QtGlobal>

#include "tests/support/temp_dir.h"

namespace ensil::test {

class ScopedCacheHome {
public:
    ScopedCacheHome()
        : m_hadPrevious(qEnvironmentVariableIsSet("XDG_CACHE_HOME")),
          m_previous(qgetenv("XDG_CACHE_HOME")) {
        qputenv("XDG_CACHE_HOME", QByteArray::fromStdString(m_dir.path().string()));
    }
    ScopedCacheHome(const ScopedCacheHome&) = delete;
    ScopedCacheHome& operator=(const ScopedCacheHome&) = delete;
    ~ScopedCacheHome() {
        if (m_hadPrevious) {
            qputenv("XDG_CACHE_HOME", m_previous);
        } else {
            qunsetenv("XDG_CACHE_HOME");
        }
    }

private:
    TempDir m_dir;
    bool m_hadPrevious;
    QByteArray m_previous;
};

}  // namespace ensil::test
