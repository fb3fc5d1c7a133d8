// Build-time tool: renders an SVG into a square raster image (PNG for the hicolor icon theme, ICO
// for the Windows executable), so the rasters never drift from the one SVG that is committed.
// Usage: rasterize_svg INPUT.svg OUTPUT.(png|ico) SIZE
#include <QCoreApplication>
#include <QImage>
#include <QImageWriter>
#include <QPainter>
#include <QSvgRenderer>
#include <QTextStream>

namespace {
constexpr int kMaxSize = 1024;

int fail(const QString& message) {
    QTextStream(stderr) << "rasterize_svg: " << message << '\n';
    return 1;
}
}  // namespace

int main(int argc, char* argv[]) {
    // For the image-format plugins (ICO) that QImageWriter loads.
    const QCoreApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() != 4) return fail(QStringLiteral("usage: rasterize_svg INPUT.svg OUTPUT SIZE"));

    bool isNumber = false;
    const int size = args.at(3).toInt(&isNumber);
    if (!isNumber || size < 1 || size > kMaxSize) {
        return fail(QStringLiteral("SIZE must be a whole number of pixels from 1 to %1, not '%2'")
                        .arg(kMaxSize)
                        .arg(args.at(3)));
    }
    QSvgRenderer svg(args.at(1));
    if (!svg.isValid()) return fail(QStringLiteral("cannot read '%1' as SVG").arg(args.at(1)));

    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        svg.render(&painter);
    }
    QImageWriter writer(args.at(2));
    if (!writer.write(image)) {
        return fail(QStringLiteral("cannot write '%1': %2").arg(args.at(2), writer.errorString()));
    }
    return 0;
}
