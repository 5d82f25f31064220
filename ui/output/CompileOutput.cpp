// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/CompileOutput.h"

#include "compiler/Compiler.h"
#include "project/TextPlace.h"

#include <QHeaderView>
#include <QIcon>
#include <QPainter>

namespace rs::ui {

namespace {

constexpr int kKindRole = Qt::UserRole;
constexpr int kStationRole = Qt::UserRole + 1;
constexpr int kLineRole = Qt::UserRole + 2;
constexpr int kColumnRole = Qt::UserRole + 3;
constexpr int kAddressRole = Qt::UserRole + 4;

QString placeText(const project::TextPlace& place, int column) {
    using Kind = project::TextPlace::Kind;
    switch (place.kind) {
    case Kind::UnitCode:
        return CompileOutput::tr("Pluto %1, line %2:%3")
            .arg(place.station)
            .arg(place.line)
            .arg(column);
    case Kind::Unit:
        return CompileOutput::tr("Pluto %1, settings").arg(place.station);
    case Kind::Variable:
        return CompileOutput::tr("Pluto %1, %2")
            .arg(place.station)
            .arg(QString::fromStdString(lang::toString(place.address)));
    case Kind::Project:
        break;
    }
    return CompileOutput::tr("Project");
}

} // namespace

CompileOutput::CompileOutput(QWidget* parent) : QTreeWidget(parent) {
    setColumnCount(2);
    setHeaderLabels({tr("Place"), tr("Message")});
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(PlaceColumn, QHeaderView::ResizeToContents);
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        if (!item->data(PlaceColumn, kKindRole).isValid())
            return;
        project::TextPlace place;
        place.kind =
            static_cast<project::TextPlace::Kind>(item->data(PlaceColumn, kKindRole).toInt());
        place.station = item->data(PlaceColumn, kStationRole).toInt();
        place.line = item->data(PlaceColumn, kLineRole).toInt();
        place.address =
            lang::readAddressWord(item->data(PlaceColumn, kAddressRole).toString().toStdString())
                .address;
        emit placeActivated(place, item->data(PlaceColumn, kColumnRole).toInt());
    });
}

void CompileOutput::showRunning(const QString& projectName) {
    clear();
    auto* item = new QTreeWidgetItem(this);
    item->setText(MessageColumn, tr("Compiling %1...").arg(projectName));
}

void CompileOutput::showResult(const QString& projectName, std::string_view canonicalText,
                               const compiler::CompileResult& result, const QString& writtenFile,
                               const QString& writeError) {
    clear();
    const QIcon errorIcon(QStringLiteral(":/icons/error.svg"));
    const QIcon warningIcon(QStringLiteral(":/icons/warning.svg"));
    auto* start = new QTreeWidgetItem(this);
    start->setText(MessageColumn, tr("Compiling %1").arg(projectName));
    const project::TextPlaces places(canonicalText);
    // Made apart and added at once: a large project's tens of thousands of
    // rows, one insertion each, would each tell the view.
    QList<QTreeWidgetItem*> rows;
    rows.reserve(static_cast<qsizetype>(result.diagnostics.size()));
    for (const auto& diagnostic : result.diagnostics) {
        const bool error = diagnostic.severity == lang::Severity::Error;
        const project::TextPlace place = places.of(diagnostic.line);
        auto* item = new QTreeWidgetItem;
        rows.append(item);
        item->setIcon(PlaceColumn, error ? errorIcon : warningIcon);
        item->setText(PlaceColumn, placeText(place, diagnostic.column));
        item->setToolTip(PlaceColumn, tr("Line %1 of the project file").arg(diagnostic.line));
        const QString message = QString::fromStdString(diagnostic.message);
        item->setText(MessageColumn, (error ? tr("error: %1") : tr("warning: %1")).arg(message));
        item->setToolTip(MessageColumn, message);
        item->setData(PlaceColumn, kKindRole, static_cast<int>(place.kind));
        item->setData(PlaceColumn, kStationRole, place.station);
        item->setData(PlaceColumn, kLineRole, place.line);
        item->setData(PlaceColumn, kColumnRole, diagnostic.column);
        item->setData(PlaceColumn, kAddressRole,
                      QString::fromStdString(lang::toString(place.address)));
    }
    addTopLevelItems(rows);
    if (!writtenFile.isEmpty()) {
        auto* written = new QTreeWidgetItem(this);
        written->setText(MessageColumn, tr("Wrote %1").arg(writtenFile));
    }
    if (!writeError.isEmpty()) {
        auto* failed = new QTreeWidgetItem(this);
        failed->setIcon(PlaceColumn, errorIcon);
        failed->setText(MessageColumn,
                        tr("error: the compiled file was not written: %1").arg(writeError));
        failed->setToolTip(MessageColumn, writeError);
    }
    // The original tool's closing line, word for word.
    auto* closing = new QTreeWidgetItem(this);
    closing->setText(MessageColumn,
                     QStringLiteral("%1 Error(s) detected Result=%2")
                         .arg(result.errors())
                         .arg(result.errors() ? QStringLiteral("FAILED") : QStringLiteral("OK")));
    QFont bold = closing->font(MessageColumn);
    bold.setBold(true);
    closing->setFont(MessageColumn, bold);
    scrollToItem(closing);
}

QString CompileOutput::closingLine() const {
    const int count = topLevelItemCount();
    return count ? topLevelItem(count - 1)->text(MessageColumn) : QString();
}

void CompileOutput::paintEvent(QPaintEvent* event) {
    QTreeWidget::paintEvent(event);
    if (topLevelItemCount() > 0)
        return;
    QPainter painter(viewport());
    painter.setPen(palette().color(QPalette::Disabled, QPalette::Text));
    painter.drawText(viewport()->rect(), Qt::AlignCenter,
                     tr("Build > Compile (F7) checks the project and writes the compiled file."));
}

} // namespace rs::ui
