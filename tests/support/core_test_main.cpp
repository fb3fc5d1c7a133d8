// main() for test suites that need Qt's event loop but no display (the workbench's controllers):
// a QCoreApplication, so that a widget or a window made by mistake fails at once.
#include <gtest/gtest.h>

#include <QCoreApplication>

#include "tests/support/private_user_folders.h"

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    const ensil::test::PrivateUserFolders userFolders;
    QCoreApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("ensil-tests"));
    QCoreApplication::setApplicationName(QStringLiteral("ensil-tests"));
    return RUN_ALL_TESTS();
}
