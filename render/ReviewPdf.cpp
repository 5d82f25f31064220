// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReviewPdf.h"

#include "NetworkPainter.h"
#include "review/Alignment.h"

#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>

#include <algorithm>

namespace rs::render {

namespace {

// Page coordinates are points (1/72 inch) on A4 landscape.
constexpr int kResolution = 72;
constexpr qreal kMargin = 36;

// An element as a reviewer compares it: what it is and what it acts on, not
// what it is called.
std::string elementKey(const ladder::ElementLayout& element) {
    return std::to_string(static_cast<int>(element.kind)) + (element.negated ? "/" : " ") +
           element.address.toStdString() + ' ' + element.text.toStdString();
}

std::vector<std::string> elementKeys(const ladder::NetworkLayout& layout) {
    std::vector<std::string> keys;
    for (const auto& element : layout.elements)
        keys.push_back(elementKey(element));
    return keys;
}

// The cells of the elements that differ between the two versions of a
// network, lined up as the networks themselves are (review/Alignment.h).
struct Marks {
    std::vector<QRectF> before;
    std::vector<QRectF> after;
};

Marks changedElements(const ladder::NetworkLayout& before, const ladder::NetworkLayout& after) {
    Marks marks;
    for (const review::Pairing& pairing : review::align(elementKeys(before), elementKeys(after))) {
        if (pairing.kind == review::Pairing::Same)
            continue;
        if (pairing.oldIndex >= 0)
            marks.before.push_back(
                before.elements[static_cast<std::size_t>(pairing.oldIndex)].cell);
        if (pairing.newIndex >= 0)
            marks.after.push_back(after.elements[static_cast<std::size_t>(pairing.newIndex)].cell);
    }
    return marks;
}

class ReviewPages {
public:
    ReviewPages(QPdfWriter& writer, const Review& review)
        : m_writer(writer), m_review(review), m_painter(&writer) {
        m_area = QRectF(QPointF(0, 0), writer.pageLayout().paintRect(QPageLayout::Point).size());
    }

    bool ok() const { return m_painter.isActive(); }

    void paint() {
        firstPage();
        for (const ReviewNetwork& network : m_review.networks) {
            m_writer.newPage();
            ++m_page;
            networkPage(network);
        }
        m_painter.end();
    }

private:
    qreal line(qreal y, const QString& text, qreal size, bool bold = false) {
        QFont font = m_painter.font();
        font.setPointSizeF(size);
        font.setBold(bold);
        m_painter.setFont(font);
        m_painter.drawText(QRectF(0, y, m_area.width(), size * 2), Qt::AlignLeft | Qt::AlignTop,
                           text);
        return y + size * 1.6;
    }

    void footer() {
        QFont font = m_painter.font();
        font.setPointSizeF(8);
        font.setBold(false);
        m_painter.setFont(font);
        m_painter.drawText(QRectF(0, m_area.height() - 12, m_area.width(), 12),
                           Qt::AlignRight | Qt::AlignBottom,
                           QStringLiteral("%1 — %2").arg(m_review.title).arg(m_page));
    }

    void firstPage() {
        qreal y = line(0, m_review.title, 16, true) + 6;
        for (const QString& text : m_review.summary)
            y = line(y, text, 10);
        y += 8;
        // As many changes as the page holds; every one has its own page after.
        const qreal signing = m_area.height() - 90;
        for (const QString& text : m_review.changes) {
            if (y > signing - 30) {
                y = line(y, QStringLiteral("…"), 9);
                break;
            }
            y = line(y, text, 9);
        }
        // What a reviewer fills in by hand.
        const qreal third = m_area.width() / 3;
        int column = 0;
        for (const char* field : {"Reviewed by", "Date", "Signature"}) {
            const qreal x = third * column++;
            m_painter.drawLine(QPointF(x, signing + 40), QPointF(x + third - 24, signing + 40));
            QFont font = m_painter.font();
            font.setPointSizeF(8);
            m_painter.setFont(font);
            m_painter.drawText(QPointF(x, signing + 52), QString::fromLatin1(field));
        }
        footer();
    }

    void networkSide(const QRectF& box, const QString& label,
                     const std::optional<ladder::NetworkLayout>& layout, const QColor& mark,
                     const std::vector<QRectF>& changed) {
        m_painter.save();
        m_painter.setPen(QPen(mark, 2));
        m_painter.drawRect(box);
        QFont font = m_painter.font();
        font.setPointSizeF(10);
        font.setBold(true);
        m_painter.setFont(font);
        m_painter.setPen(Qt::black);
        m_painter.drawText(box.adjusted(6, 4, -6, 0), Qt::AlignLeft | Qt::AlignTop, label);
        const QRectF inner = box.adjusted(8, 24, -8, -8);
        if (!layout) {
            font.setBold(false);
            m_painter.setFont(font);
            m_painter.drawText(inner, Qt::AlignCenter, QStringLiteral("(no network)"));
        } else if (!layout->size.isEmpty()) {
            const qreal scale = std::min({inner.width() / layout->size.width(),
                                          inner.height() / layout->size.height(), 1.0});
            m_painter.translate(inner.topLeft());
            m_painter.scale(scale, scale);
            paintNetwork(m_painter, *layout, {});
            // Over the drawing (it paints its own background), see-through so
            // the element stays readable.
            m_painter.setPen(QPen(QColor(0xE0, 0x90, 0x00), 1.5));
            m_painter.setBrush(QColor(0xFF, 0xC0, 0x40, 0x50));
            for (const QRectF& cell : changed)
                m_painter.drawRect(cell);
        }
        m_painter.restore();
    }

    void networkPage(const ReviewNetwork& network) {
        const qreal y = line(0, network.heading, 13, true) + 6;
        const qreal gap = 18;
        const qreal width = (m_area.width() - gap) / 2;
        const qreal height = m_area.height() - y - 24;
        // Framed in the colour of what happened: changed on both sides,
        // added on the new one, removed on the old one; grey where nothing is.
        const QColor changed(0xC0, 0x80, 0x00), added(0x20, 0x90, 0x30), removed(0xC0, 0x20, 0x20),
            absent(0xA0, 0xA0, 0xA0);
        const bool both = network.before && network.after;
        const Marks marks = both ? changedElements(*network.before, *network.after) : Marks{};
        const QColor before = both ? changed : network.before ? removed : absent;
        const QColor after = both ? changed : network.after ? added : absent;
        networkSide(QRectF(0, y, width, height), QStringLiteral("Before"), network.before, before,
                    marks.before);
        networkSide(QRectF(width + gap, y, width, height), QStringLiteral("After"), network.after,
                    after, marks.after);
        footer();
    }

    QPdfWriter& m_writer;
    const Review& m_review;
    QPainter m_painter;
    QRectF m_area;
    int m_page = 1;
};

} // namespace

QString writeReviewPdf(const QString& path, const Review& review) {
    QSaveFile file(path);
    const auto failure = [&](const QString& reason) {
        return QStringLiteral("cannot write %1: %2").arg(path, reason);
    };
    if (!file.open(QIODevice::WriteOnly))
        return failure(file.errorString());
    {
        QPdfWriter writer(&file);
        writer.setResolution(kResolution);
        writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Landscape,
                                         QMarginsF(kMargin, kMargin, kMargin, kMargin),
                                         QPageLayout::Point));
        writer.setTitle(review.title);
        writer.setCreator(QStringLiteral("Rungsmith"));
        ReviewPages pages(writer, review);
        if (!pages.ok())
            return failure(QStringLiteral("the PDF cannot be drawn"));
        pages.paint();
    }
    if (!file.commit())
        return failure(file.errorString());
    return {};
}

} // namespace rs::render
