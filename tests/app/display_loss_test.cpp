// A display server that is gone when Qt connects: ensil says so and exits 4 (app/display_loss.h),
// instead of Qt's abort and core dump; other fatal messages still abort.
#include "app/display_loss.h"

#include <gtest/gtest.h>

#include <QtGlobal>

using namespace ensil;

TEST(DisplayLoss, QtsPlatformFailureBecomesEnsilsMessageAndStatusFour) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            const app::DisplayLossGuard guard("ensil render");
            qFatal(
                "This application failed to start because no Qt platform plugin could be "
                "initialized. Reinstalling the application may fix this problem.");
        },
        ::testing::ExitedWithCode(4), "ensil render: the display server .* stopped answering");
}

TEST(DisplayLoss, OtherFatalMessagesStillAbortAndNoneOnceTheApplicationStands) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(
        {
            const app::DisplayLossGuard guard("ensil");
            qFatal("something else went wrong");
        },
        "something else went wrong");
    // Outside the guard (the application made), the platform's message is Qt's own again.
    EXPECT_DEATH(qFatal("no Qt platform plugin could be initialized"),
                 "no Qt platform plugin could be initialized");
    EXPECT_TRUE(app::isPlatformStartFailure(
        QtFatalMsg, QStringLiteral("no Qt platform plugin could be initialized")));
    EXPECT_FALSE(app::isPlatformStartFailure(
        QtWarningMsg, QStringLiteral("no Qt platform plugin could be initialized")));
}
