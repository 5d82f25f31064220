// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/CompileOutput.h"

#include "compiler/Compiler.h"
#include "project/TextPlace.h"

#include <QHeaderView>
#include <QPainter>

namespace rs::ui {

CompileOutput::CompileOutput(QWidget* parent)
    : QTreeView(parent), m_model(new CompileOutputModel(this)) {
    setModel(m_model);
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(PlaceColumn, QHeaderView::ResizeToContents);
    connect(this, &QAbstractItemView::activated, this, [this](const QModelIndex& index) {
        const CompileOutputModel::Row& row = m_model->row(index.row());
        if (row.finding)
            emit placeActivated(row.place, row.column);
    });
}

void CompileOutput::clear() {
    m_model->setRows({});
}

void CompileOutput::showRunning(const QString& projectName) {
    CompileOutputModel::Row running;
    running.text = tr("Compiling %1...").arg(projectName);
    std::vector<CompileOutputModel::Row> rows;
    rows.push_back(std::move(running));
    m_model->setRows(std::move(rows));
}

void CompileOutput::showResult(const QString& projectName, std::string_view canonicalText,
                               const compiler::CompileResult& result, const QString& writtenFile,
                               const QString& writeError) {
    std::vector<CompileOutputModel::Row> rows;
    rows.reserve(result.diagnostics.size() + 4);
    CompileOutputModel::Row start;
    start.text = tr("Compiling %1").arg(projectName);
    rows.push_back(std::move(start));
    const project::TextPlaces places(canonicalText);
    for (const auto& diagnostic : result.diagnostics) {
        CompileOutputModel::Row finding;
        finding.finding = true;
        finding.severity = diagnostic.severity;
        finding.place = places.of(diagnostic.line);
        finding.column = diagnostic.column;
        finding.fileLine = diagnostic.line;
        finding.message = diagnostic.message;
        rows.push_back(std::move(finding));
    }
    if (!writtenFile.isEmpty()) {
        CompileOutputModel::Row written;
        written.text = tr("Wrote %1").arg(writtenFile);
        rows.push_back(std::move(written));
    }
    if (!writeError.isEmpty()) {
        CompileOutputModel::Row failed;
        failed.severity = lang::Severity::Error;
        failed.text = tr("error: the compiled file was not written: %1").arg(writeError);
        failed.toolTip = writeError;
        rows.push_back(std::move(failed));
    }
    // The original tool's closing line, word for word.
    CompileOutputModel::Row closing;
    closing.text = QStringLiteral("%1 Error(s) detected Result=%2")
                       .arg(result.errors())
                       .arg(result.errors() ? QStringLiteral("FAILED") : QStringLiteral("OK"));
    closing.bold = true;
    rows.push_back(std::move(closing));
    m_model->setRows(std::move(rows));
    scrollToBottom();
}

QString CompileOutput::closingLine() const {
    const int count = rowCount();
    return count ? text(count - 1, MessageColumn) : QString();
}

int CompileOutput::rowCount() const {
    return m_model->rowCount();
}

QString CompileOutput::text(int row, Column column) const {
    return m_model->data(m_model->index(row, column), Qt::DisplayRole).toString();
}

void CompileOutput::paintEvent(QPaintEvent* event) {
    QTreeView::paintEvent(event);
    if (rowCount() > 0)
        return;
    QPainter painter(viewport());
    painter.setPen(palette().color(QPalette::Disabled, QPalette::Text));
    painter.drawText(viewport()->rect(), Qt::AlignCenter,
                     tr("Build > Compile (F7) checks the project and writes the compiled file."));
}

} // namespace rs::ui
