// Compiles and owns the shader programs. Sources are embedded at build time (Qt resources under
// :/ensil/shaders/); setting the environment variable ENSIL_SHADER_DIR to the source tree's
// gl/shaders folder loads them from disk instead, so a developer can edit shaders without
// rebuilding. GUI thread only, with the owning context current.
#pragma once

#include <QOpenGLShaderProgram>
#include <QString>
#include <map>
#include <memory>
#include <stdexcept>

namespace ensil::gl {

class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The files of a program, without their extensions; an empty vertex or fragment name means
// the program's own name, an empty geometry name no geometry shader.
struct ShaderFiles {
    QString vertex;
    QString geometry;
    QString fragment;
};

class ShaderLibrary {
public:
    // Returns the program built from VERTEX.vert, GEOMETRY.geom (if named) and FRAGMENT.frag,
    // compiling it on first use. Throws ShaderError with the compiler's log if it does not
    // compile or link.
    QOpenGLShaderProgram& program(const QString& name, const ShaderFiles& files = {});
    // Destroys every program; the context that created them must be current.
    void clear() { m_programs.clear(); }

    // The text of shaders/FILE (embedded, or from ENSIL_SHADER_DIR), with each line
    // `#include "OTHER"` replaced by the text of shaders/OTHER. Throws ShaderError.
    static QByteArray source(const QString& file);

private:
    std::map<QString, std::unique_ptr<QOpenGLShaderProgram>> m_programs;
};

}  // namespace ensil::gl
