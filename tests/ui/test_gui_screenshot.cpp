// `rollsim gui PROJECT --screenshot FILE.png` through the real binary under Xvfb: a non-blank PNG of the requested
// size, exit 0; an invalid project: the validator's message on stderr and exit 2.
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

namespace {

struct Run {
  int code;
  QString out, err;
};

Run rollsim(const QStringList& args) {
  QProcess p;
  p.start(QStringLiteral(ROLLSIM_BINARY), args);
  if (!p.waitForFinished(90000)) {
    p.kill();
    p.waitForFinished();
    return {-1, {}, QStringLiteral("timeout")};
  }
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardOutput()),
          QString::fromUtf8(p.readAllStandardError())};
}

/// Per-pixel variance of the grey level over the image, and the number of distinct colours (sampled).
double grey_variance(const QImage& image, int* colours) {
  double sum = 0, sum2 = 0;
  long n = 0;
  QSet<QRgb> seen;
  for (int y = 0; y < image.height(); y += 3)
    for (int x = 0; x < image.width(); x += 3) {
      const QRgb c = image.pixel(x, y);
      seen.insert(c);
      const double g = qGray(c);
      sum += g;
      sum2 += g * g;
      ++n;
    }
  *colours = seen.size();
  const double mean = sum / static_cast<double>(n);
  return sum2 / static_cast<double>(n) - mean * mean;
}

}  // namespace

class TestGuiScreenshot : public QObject {
  Q_OBJECT

 private slots:
  void screenshot_of_a_sample_is_not_blank() {
    QTemporaryDir dir;
    const QString png = dir.filePath(QStringLiteral("plate.png"));
    const Run r = rollsim({QStringLiteral("gui"), QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json"),
                           QStringLiteral("--screenshot"), png, QStringLiteral("--size"), QStringLiteral("1200x800")});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QImage image(png);
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(1200, 800));
    int colours = 0;
    const double variance = grey_variance(image, &colours);
    QVERIFY2(variance > 100, qPrintable(QStringLiteral("grey variance %1").arg(variance)));
    QVERIFY2(colours > 50, qPrintable(QStringLiteral("%1 colours").arg(colours)));
    // the mesh is drawn in the centre of the view in the body's categorical colour (not only background)
    const QImage centre = image.copy(QRect(350, 200, 300, 250));
    int mesh_like = 0;
    for (int y = 0; y < centre.height(); y += 2)
      for (int x = 0; x < centre.width(); x += 2) {
        const QColor c = centre.pixelColor(x, y);
        if (c.blue() > c.red() + 40) ++mesh_like;  // the first body colour is blue
      }
    QVERIFY2(mesh_like > 500, qPrintable(QStringLiteral("%1 body-coloured pixels").arg(mesh_like)));
  }

  void invalid_project_exits_2_with_the_message() {
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"dimension": 2, "materials": [{"name": "m", "E": -1, "nu": 0.3}], "bodies": []})");
    f.close();
    const QString png = dir.filePath(QStringLiteral("bad.png"));
    const Run r = rollsim({QStringLiteral("gui"), bad, QStringLiteral("--screenshot"), png});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QStringLiteral("materials[0].E: must be a finite number > 0, got -1")), qPrintable(r.err));
    QVERIFY(!QFileInfo::exists(png));
  }
};

QTEST_GUILESS_MAIN(TestGuiScreenshot)
#include "test_gui_screenshot.moc"
