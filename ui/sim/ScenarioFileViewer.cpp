// SPDX-License-Identifier: GPL-3.0-or-later
#include "ScenarioFileViewer.h"

#include "project/ProjectFile.h"

#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QUrl>
#include <QVBoxLayout>

namespace rs::ui {

ScenarioFileViewer::ScenarioFileViewer(QWidget* parent)
    : QDialog(parent), m_text(new QPlainTextEdit(this)), m_where(new QLabel(this)) {
    setObjectName(QStringLiteral("scenarioFileViewer"));
    m_text->setReadOnly(true);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_text->setLineWrapMode(QPlainTextEdit::NoWrap);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* open = buttons->addButton(tr("&Open in Editor"), QDialogButtonBox::ActionRole);
    connect(open, &QPushButton::clicked, this,
            [this] { QDesktopServices::openUrl(QUrl::fromLocalFile(m_path)); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_where);
    layout->addWidget(m_text, 1);
    layout->addWidget(buttons);
    resize(640, 420);
}

QString ScenarioFileViewer::showLine(const QString& path, int line) {
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty())
        return file.error;
    m_path = path;
    setWindowTitle(tr("%1 (read-only)").arg(QFileInfo(path).fileName()));
    m_where->setText(tr("%1, line %2").arg(QDir::toNativeSeparators(path)).arg(line));
    m_text->setPlainText(QString::fromStdString(file.text));
    const QTextBlock block = m_text->document()->findBlockByNumber(line - 1);
    QTextCursor cursor(block);
    cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
    m_text->setTextCursor(cursor);
    m_text->centerCursor();
    return {};
}

int ScenarioFileViewer::currentLine() const {
    return m_text->textCursor().blockNumber() + 1;
}

} // namespace rs::ui
