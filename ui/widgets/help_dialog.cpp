#include "widgets/help_dialog.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QFileInfo>
#include <QPushButton>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextImageFormat>
#include <QVBoxLayout>

namespace auv::ui {

HelpDialog::HelpDialog(const QString& markdown_file, QWidget* parent) : QDialog(parent) {
  setObjectName("help_dialog");
  setWindowTitle(tr("auvballast - technician's guide"));
  browser_ = new QTextBrowser;
  browser_->setObjectName("help_browser");
  browser_->setOpenExternalLinks(true);
  QFile f(markdown_file);
  if (f.open(QIODevice::ReadOnly | QIODevice::Text)) {
    // Relative image links in the guide resolve against its folder.
    browser_->setSearchPaths({QFileInfo(markdown_file).absolutePath()});
    browser_->setMarkdown(QString::fromUtf8(f.readAll()));
    // The screenshots are full wizard size: show them at a readable width
    // inside the guide (the height follows, keeping the aspect ratio).
    QTextCursor c(browser_->document());
    for (QTextBlock b = browser_->document()->begin(); b.isValid(); b = b.next()) {
      for (auto it = b.begin(); !it.atEnd(); ++it) {
        const QTextFragment frag = it.fragment();
        if (!frag.charFormat().isImageFormat()) continue;
        QTextImageFormat img = frag.charFormat().toImageFormat();
        img.setWidth(600);
        c.setPosition(frag.position());
        c.setPosition(frag.position() + frag.length(), QTextCursor::KeepAnchor);
        c.setCharFormat(img);
      }
    }
  } else {
    browser_->setPlainText(tr("The guide was not found at %1.").arg(markdown_file));
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
  buttons->button(QDialogButtonBox::Close)->setText(tr("&Close"));
  buttons->button(QDialogButtonBox::Close)->setMinimumHeight(32);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* lay = new QVBoxLayout(this);
  lay->addWidget(browser_);
  lay->addWidget(buttons);
  resize(820, 700);
}

}  // namespace auv::ui
