// SPDX-License-Identifier: GPL-3.0-or-later
// The networks of a ladder page on paper: printed, or written as PDF.
#include "LadderPage.h"

#include "NetworkItem.h"
#include "NetworkPainter.h"
#include "document/ProjectDocument.h"
#include "project/SaveFileCommit.h"

#include <QDir>
#include <QFileDialog>
#include <QMessageBox>
#include <QPainter>
#include <QPdfWriter>
#include <QPrintDialog>
#include <QPrinter>
#include <QSaveFile>

#include <algorithm>

namespace rs::ui {

void LadderPage::paintPages(QPagedPaintDevice& device, const QString& title) const {
    QPainter painter(&device);
    const QRectF page(0, 0, device.width(), device.height());
    qreal width = 0;
    for (const auto& step : m_items)
        for (NetworkItem* item : step)
            width = std::max(width, item->layout().size.width());
    if (width <= 0)
        return;
    const qreal scale = std::min<qreal>(page.width() / width, device.logicalDpiX() / 96.0);
    render::LadderStyle style; // paper is white whatever the theme
    QFont titleFont = style.font(style.titlePixelSize + 2, true);
    qreal y = 0;
    painter.setFont(titleFont);
    painter.drawText(QRectF(0, 0, page.width(), 40 * scale), Qt::AlignLeft | Qt::AlignVCenter,
                     title);
    y = 48 * scale;
    for (std::size_t s = 0; s < m_items.size(); ++s) {
        if (m_sequence != 0) {
            if (y + 40 * scale > page.height()) {
                device.newPage();
                y = 0;
            }
            painter.setFont(titleFont);
            painter.drawText(QRectF(0, y, page.width(), 30 * scale),
                             Qt::AlignLeft | Qt::AlignVCenter,
                             QString::fromStdString(lang::toString(m_steps[s].address)));
            y += 34 * scale;
        }
        for (NetworkItem* item : m_items[s]) {
            const QSizeF size = item->layout().size * scale;
            if (y + size.height() > page.height() && y > 0) {
                device.newPage();
                y = 0;
            }
            painter.save();
            painter.translate(0, y);
            painter.scale(scale, scale);
            render::paintNetwork(painter, item->layout(), style);
            painter.restore();
            y += size.height() + kNetworkGap * scale;
        }
    }
}

bool LadderPage::exportPdf(const QString& path) {
    QString file = path;
    if (file.isEmpty()) {
        file = QFileDialog::getSaveFileName(this, tr("Export PDF"), QString(),
                                            tr("PDF documents (*.pdf)"));
        if (file.isEmpty())
            return false;
    }
    // Through a save file: a failed export leaves an older PDF as it was.
    QSaveFile out(file);
    QString error;
    if (out.open(QIODevice::WriteOnly)) {
        {
            QPdfWriter writer(&out);
            writer.setPageSize(QPageSize(QPageSize::A4));
            writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
            writer.setResolution(150);
            writer.setTitle(pageTitle());
            paintPages(writer, writer.title());
        }
        error = project::commitSaveFile(out);
    } else {
        error = out.errorString();
    }
    if (!error.isEmpty()) {
        setMessage(tr("Could not export to %1.").arg(QDir::toNativeSeparators(file)));
        QMessageBox::warning(
            this, tr("Export PDF"),
            tr("Could not export to %1: %2").arg(QDir::toNativeSeparators(file), error));
        return false;
    }
    setMessage(tr("Exported to %1.").arg(file));
    return true;
}

void LadderPage::print() {
    QPrinter printer(QPrinter::HighResolution);
    QPrintDialog dialog(&printer, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    paintPages(printer, pageTitle());
}

} // namespace rs::ui
