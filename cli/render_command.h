// `ensil render FILE...|--demo --iso X --out FILE.png [--size WxH] [--mode shaded|spaghetti|
// surfaces] [--clusters K] [--linkage L] [--mean|--no-mean] [--thickness T] [--exaggeration F]
// [--azimuth A --elevation E] [--frames N] [--no-cache] [--json]`: draws an ensemble's
// silhouettes into an offscreen framebuffer and writes a PNG, with no window. Needs a
// QGuiApplication and an X display (Xvfb will do). Main thread.
#pragma once

#include <QStringList>
#include <QTextStream>

namespace ensil::cli {

int runRenderCommand(const QStringList& args, QTextStream& out, QTextStream& err);

}  // namespace ensil::cli
