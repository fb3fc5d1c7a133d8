// Progress of long command-line runs on stderr: only after a second, at most once a second,
// one line rewritten in place and ended before anything else is printed.
#include "cli/command_progress.h"

#include <gtest/gtest.h>

#include <QString>
#include <QTextStream>

using namespace ensil;
using namespace std::chrono_literals;

namespace {
struct FakeClock {
    std::chrono::steady_clock::time_point now{};
    cli::CommandProgress::Clock clock() {
        return [this] { return now; };
    }
};
}  // namespace

TEST(CommandProgress, WritesOnceASecondAfterTheFirstSecondAndEndsItsLine) {
    QString text;
    QTextStream err(&text);
    FakeClock time;
    {
        cli::CommandProgress progress(err, QStringLiteral("ensil preprocess"), true, time.clock());
        const data::Progress reading = progress.callback(QStringLiteral("reading"));
        reading(0.10);
        EXPECT_TRUE(text.isEmpty()) << "a run under a second prints nothing";
        time.now += 1500ms;
        reading(0.25);
        EXPECT_EQ(text, QStringLiteral("\rensil preprocess: reading, 25 %"));
        time.now += 500ms;
        reading(0.50);
        EXPECT_EQ(text, QStringLiteral("\rensil preprocess: reading, 25 %")) << "within a second";
        time.now += 1s;
        reading(0.75);
        EXPECT_TRUE(text.endsWith(QStringLiteral("\rensil preprocess: reading, 75 %")));
        // Another stage is shown at once, padded over the longer text before it.
        progress.report(QStringLiteral("meshing"), 0.0);
        EXPECT_TRUE(text.endsWith(QStringLiteral("\rensil preprocess: meshing, 0 % ")))
            << text.toStdString();
        // A message printed now starts on a line of its own.
        progress.endLine();
        EXPECT_TRUE(text.endsWith(QStringLiteral("\n")));
        const qsizetype ended = text.size();
        progress.endLine();
        EXPECT_EQ(text.size(), ended) << "one newline, not one per call";
        time.now += 1s;
        progress.report(QStringLiteral("meshing"), 1.0);
    }
    EXPECT_TRUE(text.endsWith(QStringLiteral("\rensil preprocess: meshing, 100 %\n")))
        << "the last line is ended when the run ends: " << text.toStdString();
}

TEST(CommandProgress, WritesNothingWhenNotShown) {
    QString text;
    QTextStream err(&text);
    FakeClock time;
    {
        cli::CommandProgress progress(err, QStringLiteral("ensil preprocess"), false, time.clock());
        EXPECT_FALSE(progress.callback(QStringLiteral("reading"))) << "no callback to call";
        time.now += 5s;
        progress.report(QStringLiteral("reading"), 0.5);
        progress.endLine();
    }
    EXPECT_TRUE(text.isEmpty());
    // --quiet, and a stderr that is not a terminal (a test's is a pipe or a file), show none.
    EXPECT_FALSE(cli::CommandProgress::shownOnThisTerminal(true));
}
