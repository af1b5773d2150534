// SPDX-License-Identifier: GPL-3.0-or-later
// A probe preloaded into MeshLab's GUI (LD_PRELOAD) by gui_dialog_test.sh: it measures the filter
// dialog as MeshLab 2020.09 lays it out, which no screenshot can assert.
//
// MeshLab shows each parameter's help as a word-wrapped label (richparameterwidgets.cpp: at least
// 250 px wide) in a third column that the Help button toggles, then resizes the floating dialog
// with QWidget::adjustSize, which caps a window at 2/3 of the screen: when the dialog with its help
// would be taller, every row is squeezed and each paragraph loses its last line. So, once the
// dialog titled $ELASTICA_DIALOG_PROBE_TITLE is shown and the file "$ELASTICA_DIALOG_PROBE_OUT.help"
// exists (the test creates it after its first screenshot), the probe clicks Help and writes to
// $ELASTICA_DIALOG_PROBE_OUT one line per visible word-wrapped label (the filter's description
// first, then the help of each parameter):
//   FIT|CLIPPED <width>x<height> needs <height for that width> | <text>
// CLIPPED: the label is shorter than its text needs at its width, or reaches outside the dialog.
// The last line is "done".
#include <QApplication>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QTextDocument>
#include <QTextStream>
#include <QTimer>
#include <QWidget>

#include <memory>

namespace {

QString plainText(const QString& richText) {
  QTextDocument d;
  d.setHtml(richText);
  return d.toPlainText().simplified();
}

QWidget* shownWindow(const QString& title) {
  for (QWidget* w : QApplication::topLevelWidgets())
    if (w->isVisible() && w->windowTitle() == title) return w;
  return nullptr;
}

void report(QWidget* dialog, const QString& path) {
  QFile file(path + ".part");
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) return;
  QTextStream out(&file);
  const QRect screen = dialog->screen()->geometry();
  out << "dialog " << dialog->width() << "x" << dialog->height() << " on a " << screen.width() << "x"
      << screen.height() << " screen, font " << dialog->font().family() << " " << dialog->font().pointSizeF() << " pt\n";
  for (QLabel* label : dialog->findChildren<QLabel*>()) {
    if (!label->isVisible() || !label->wordWrap()) continue;
    const int needs = label->heightForWidth(label->width());
    const QRect inDialog(label->mapTo(dialog, QPoint(0, 0)), label->size());
    const bool fits = label->height() >= needs && dialog->rect().contains(inDialog);
    out << (fits ? "FIT " : "CLIPPED ") << label->width() << "x" << label->height() << " needs " << needs << " | "
        << plainText(label->text()) << "\n";
  }
  out << "done\n";
  file.close();
  QFile::remove(path);
  file.rename(path);
}

void startProbe() {
  const QString title = qEnvironmentVariable("ELASTICA_DIALOG_PROBE_TITLE");
  const QString path = qEnvironmentVariable("ELASTICA_DIALOG_PROBE_OUT");
  if (title.isEmpty() || path.isEmpty()) return;
  auto* timer = new QTimer(qApp);
  auto ticksSinceHelp = std::make_shared<int>(-1);
  QObject::connect(timer, &QTimer::timeout, [=] {
    QWidget* dialog = shownWindow(title);
    if (dialog == nullptr) return;
    if (*ticksSinceHelp < 0) {
      if (!QFileInfo::exists(path + ".help")) return;
      for (QPushButton* b : dialog->findChildren<QPushButton*>())
        if (b->text() == "Help") b->click();
      *ticksSinceHelp = 0;
      return;
    }
    if (++*ticksSinceHelp < 3) return;  // let the dialog settle after its resize
    report(dialog, path);
    timer->stop();
  });
  timer->start(200);
}

}  // namespace

// Runs in QCoreApplication's constructor, before MeshLab builds its windows.
Q_COREAPP_STARTUP_FUNCTION(startProbe)
