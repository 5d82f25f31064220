// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110LadderView.h"

#include "NetworkPainter.h"
#include "ladder/LadderDrawing.h"
#include "pl110/RungLayout.h"
#include "pl110/Rungs.h"

#include <QContextMenuEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>

#include <algorithm>

namespace rs::ui {

namespace {

constexpr qreal kHeadingHeight = 30;
constexpr qreal kRungGap = 6;

} // namespace

Pl110LadderView::Pl110LadderView(QWidget* parent) : QAbstractScrollArea(parent) {
    setObjectName(QStringLiteral("pl110LadderView"));
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setMouseTracking(true);
    updateStyle();
}

void Pl110LadderView::setProgram(const pl110::Program& program) {
    m_rungs.clear();
    m_headings.clear();
    qreal top = 0;
    qreal width = 0;
    bool inInit = false;
    bool inMain = false;
    for (const pl110::NumberedRung& numbered : pl110::numberedRungs(program)) {
        if (numbered.init && !inInit) {
            m_headings.push_back({top, tr("INIT — runs once, before the first scan")});
            top += kHeadingHeight;
            inInit = true;
        }
        if (!numbered.init && !inMain) {
            m_headings.push_back({top, tr("MAIN — runs every scan")});
            top += kHeadingHeight;
            inMain = true;
        }
        pl110::RungLayoutContext context;
        context.title = tr("Rung %1").arg(numbered.number);
        context.comment = QString::fromStdString(numbered.comment);
        context.statement = static_cast<std::uint32_t>(numbered.number);
        PlacedRung placed{pl110::layoutRung(*numbered.rung, context), top,
                          numbered.line->location.line};
        top += placed.layout.size.height() + kRungGap;
        width = std::max(width, placed.layout.size.width());
        m_rungs.push_back(std::move(placed));
    }
    if (m_rungs.empty())
        m_headings.push_back(
            {0, tr("The program has no rungs yet: write them on the Program page.")});
    m_size = QSizeF(std::max(width, 400.0), top + kHeadingHeight);
    updateScrollBars();
    viewport()->update();
}

void Pl110LadderView::setPower(std::optional<render::PowerSnapshot> power) {
    m_power = std::move(power);
    viewport()->update();
}

bool Pl110LadderView::showRung(int number) {
    if (number < 1 || number > rungCount())
        return false;
    verticalScrollBar()->setValue(
        static_cast<int>(m_rungs[static_cast<std::size_t>(number - 1)].top));
    return true;
}

QPointF Pl110LadderView::contentPoint(const QPoint& viewportPoint) const {
    return QPointF(viewportPoint) +
           QPointF(horizontalScrollBar()->value(), verticalScrollBar()->value());
}

const Pl110LadderView::PlacedRung* Pl110LadderView::rungAt(const QPointF& point) const {
    const auto after = std::upper_bound(m_rungs.begin(), m_rungs.end(), point.y(),
                                        [](qreal y, const PlacedRung& r) { return y < r.top; });
    if (after == m_rungs.begin())
        return nullptr;
    const PlacedRung& rung = *std::prev(after);
    return point.y() < rung.top + rung.layout.size.height() ? &rung : nullptr;
}

QString Pl110LadderView::addressAt(const QPoint& point) const {
    const QPointF content = contentPoint(point);
    const PlacedRung* rung = rungAt(content);
    if (!rung)
        return {};
    const QPointF inRung = content - QPointF(0, rung->top);
    for (const ladder::ElementLayout& element : rung->layout.elements)
        if (element.shape != ladder::Shape::Box && !element.address.isEmpty() &&
            element.cell.contains(inRung))
            return element.address;
    return {};
}

void Pl110LadderView::paintEvent(QPaintEvent*) {
    QPainter painter(viewport());
    painter.fillRect(viewport()->rect(), m_style.background);
    painter.setRenderHint(QPainter::Antialiasing);
    const qreal dx = horizontalScrollBar()->value();
    const qreal dy = verticalScrollBar()->value();
    const qreal height = viewport()->height();
    painter.setPen(m_style.ink);
    painter.setFont(m_style.font(m_style.titlePixelSize, true));
    for (const Heading& heading : m_headings) {
        if (heading.top - dy > height || heading.top + kHeadingHeight - dy < 0)
            continue;
        painter.drawText(QRectF(8 - dx, heading.top - dy, m_size.width(), kHeadingHeight),
                         Qt::AlignLeft | Qt::AlignVCenter, heading.text);
    }
    for (const PlacedRung& rung : m_rungs) {
        if (rung.top - dy > height)
            break;
        if (rung.top + rung.layout.size.height() - dy < 0)
            continue;
        painter.save();
        painter.translate(-dx, rung.top - dy);
        render::paintNetwork(painter, rung.layout, m_style, m_power ? &*m_power : nullptr);
        painter.restore();
    }
}

void Pl110LadderView::resizeEvent(QResizeEvent* event) {
    QAbstractScrollArea::resizeEvent(event);
    updateScrollBars();
}

void Pl110LadderView::updateScrollBars() {
    const QSize shown = viewport()->size();
    verticalScrollBar()->setRange(0,
                                  std::max(0, static_cast<int>(m_size.height()) - shown.height()));
    verticalScrollBar()->setPageStep(shown.height());
    verticalScrollBar()->setSingleStep(24);
    horizontalScrollBar()->setRange(0,
                                    std::max(0, static_cast<int>(m_size.width()) - shown.width()));
    horizontalScrollBar()->setPageStep(shown.width());
    horizontalScrollBar()->setSingleStep(24);
}

void Pl110LadderView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton)
        if (const QString address = addressAt(event->position().toPoint()); !address.isEmpty())
            Q_EMIT operandClicked(address);
    QAbstractScrollArea::mousePressEvent(event);
}

void Pl110LadderView::mouseDoubleClickEvent(QMouseEvent* event) {
    if (const PlacedRung* rung = rungAt(contentPoint(event->position().toPoint())))
        Q_EMIT lineActivated(rung->line);
}

void Pl110LadderView::contextMenuEvent(QContextMenuEvent* event) {
    if (const QString address = addressAt(event->pos()); !address.isEmpty())
        Q_EMIT operandMenuRequested(address, event->globalPos());
}

void Pl110LadderView::changeEvent(QEvent* event) {
    QAbstractScrollArea::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        updateStyle();
}

void Pl110LadderView::updateStyle() {
    m_style = drawingFor(palette()).style;
    viewport()->update();
}

} // namespace rs::ui
