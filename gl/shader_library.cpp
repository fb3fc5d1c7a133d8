#include "gl/shader_library.h"

#include <QFile>

namespace ensil::gl {

QByteArray ShaderLibrary::source(const QString& file) {
    const QString dir = qEnvironmentVariable("ENSIL_SHADER_DIR");
    const QString path =
        dir.isEmpty() ? QStringLiteral(":/ensil/shaders/") + file : dir + QLatin1Char('/') + file;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        throw ShaderError("cannot read shader '" + path.toStdString() +
                          "': " + f.errorString().toStdString());
    }
    // GLSL has no #include: a line `#include "FILE"` is replaced by that file's text, so a
    // function several stages share (the grid-to-display mapping, the widening of a segment on
    // screen) is written once.
    QByteArray text;
    for (const QByteArray& line : f.readAll().split('\n')) {
        const QByteArray trimmed = line.trimmed();
        if (trimmed.startsWith("#include \"") && trimmed.endsWith('"') && trimmed.size() > 11) {
            text += source(QString::fromUtf8(trimmed.mid(10, trimmed.size() - 11)));
        } else {
            text += line;
        }
        text += '\n';
    }
    return text;
}

QOpenGLShaderProgram& ShaderLibrary::program(const QString& name, const ShaderFiles& files) {
    auto found = m_programs.find(name);
    if (found != m_programs.end()) return *found->second;

    auto program = std::make_unique<QOpenGLShaderProgram>();
    const auto compile = [&](QOpenGLShader::ShaderType type, const QString& file) {
        if (!program->addShaderFromSourceCode(type, source(file))) {
            throw ShaderError("shader '" + file.toStdString() + "' does not compile:\n" +
                              program->log().toStdString());
        }
    };
    compile(QOpenGLShader::Vertex,
            (files.vertex.isEmpty() ? name : files.vertex) + QStringLiteral(".vert"));
    if (!files.geometry.isEmpty()) {
        compile(QOpenGLShader::Geometry, files.geometry + QStringLiteral(".geom"));
    }
    compile(QOpenGLShader::Fragment,
            (files.fragment.isEmpty() ? name : files.fragment) + QStringLiteral(".frag"));
    if (!program->link()) {
        throw ShaderError("shader program '" + name.toStdString() + "' does not link:\n" +
                          program->log().toStdString());
    }
    return *m_programs.emplace(name, std::move(program)).first->second;
}

}  // namespace ensil::gl
