#pragma once
#include <QDialog>

class QTextBrowser;

namespace auv::ui {

// The technician's guide (docs/user-guide.md) rendered from Markdown, with
// its screenshots, in a window that stays open beside the wizard.
class HelpDialog : public QDialog {
  Q_OBJECT
 public:
  HelpDialog(const QString& markdown_file, QWidget* parent = nullptr);
  QTextBrowser* browser() const { return browser_; }

 private:
  QTextBrowser* browser_;
};

}  // namespace auv::ui
