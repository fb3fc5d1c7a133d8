#include "gl/shader_library.h"

#include <gtest/gtest.h>

#include "tests/support/offscreen_gl.h"

using namespace ensil;

class ShaderLibraryTest : public test::OffscreenGlTest {};

TEST_F(ShaderLibraryTest, EveryEmbeddedShaderCompilesAndLinksUnderGl41Core) {
    gl::ShaderLibrary library;
    for (const char* name : {"lines", "floor_map"}) {
        QOpenGLShaderProgram& program = library.program(QString::fromLatin1(name));
        EXPECT_TRUE(program.isLinked()) << name;
    }
    // Asking again returns the same compiled program.
    EXPECT_EQ(&library.program(QStringLiteral("lines")), &library.program(QStringLiteral("lines")));
    library.clear();
}

TEST_F(ShaderLibraryTest, MissingShaderIsAnErrorNamingTheFile) {
    gl::ShaderLibrary library;
    try {
        library.program(QStringLiteral("no_such_shader"));
        FAIL() << "a missing shader was accepted";
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_shader.vert"), std::string::npos) << e.what();
    }
}
