// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QLineEdit;
class QPushButton;

namespace rs::ui {

class ProjectDocument;

// Project > Mark as Validated (issue 18, docs/review.md): who validated the
// project as it is now, and why. OK compiles it and records its signatures
// and the fingerprint of every network as the baseline, one undo step; a
// project with errors cannot be validated. The name is remembered for the
// next time.
class MarkValidatedDialog : public QDialog {
    Q_OBJECT
public:
    MarkValidatedDialog(ProjectDocument* document, QWidget* parent = nullptr);

    void accept() override;

private:
    ProjectDocument* m_document;
    QLineEdit* m_by;
    QLineEdit* m_comment;
    QPushButton* m_ok;
};

} // namespace rs::ui
