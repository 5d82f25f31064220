// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110LadderView.h"

#include "NetworkPainter.h"
#include "ladder/LadderDrawing.h"
#include "pl110/RungLayout.h"
#include "pl110/Rungs.h"

#include <QContextMenuEvent>
#include <QFontMetricsF>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>

#include <algorithm>

namespace rs::ui {

namespace {

constexpr qreal kHeadingHeight = 30;
constexpr qreal kHeadingIndent = 8;
constexpr qreal kRungGap = 6;

} // namespace

Pl110LadderView::Pl110LadderView(QWidget* parent) : QAbstractScrollArea(parent) {
    setObjectName(QStringLiteral("pl110LadderView"));
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setMouseTracking(true);
    updateStyle();
}

void Pl110LadderView::setProgram(const pl110::Program& program) {
    const ladder::ElementLayout* selected = selectedElement();
    const std::uint16_t selectedNumber = selected ? selected->element : 0;
    const int selectedRung = m_selectedRung;
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
    // The headings are as wide as their text: the page scrolls to show it whole.
    const QFontMetricsF metrics(m_style.font(m_style.titlePixelSize, true));
    for (const Heading& heading : m_headings)
        width = std::max(width, kHeadingIndent + metrics.horizontalAdvance(heading.text));
    m_size = QSizeF(width, top + kHeadingHeight);
    updateScrollBars();
    m_selectedRung = 0;
    select(std::clamp(selectedRung, 1, std::max(rungCount(), 1)), selectedNumber);
    viewport()->update();
}

const ladder::ElementLayout* Pl110LadderView::selectedElement() const {
    if (m_selectedRung < 1 || m_selectedRung > rungCount())
        return nullptr;
    const auto& elements = m_rungs[static_cast<std::size_t>(m_selectedRung - 1)].layout.elements;
    return m_selectedElement < elements.size() ? &elements[m_selectedElement] : nullptr;
}

int Pl110LadderView::selectedLine() const {
    if (m_selectedRung < 1 || m_selectedRung > rungCount())
        return 0;
    return m_rungs[static_cast<std::size_t>(m_selectedRung - 1)].line;
}

void Pl110LadderView::select(int number, std::uint16_t element) {
    const int before = m_selectedRung;
    const std::size_t beforeElement = m_selectedElement;
    if (number < 1 || number > rungCount()) {
        m_selectedRung = 0;
    } else {
        m_selectedRung = number;
        const auto& elements = m_rungs[static_cast<std::size_t>(number - 1)].layout.elements;
        const auto found = std::find_if(
            elements.begin(), elements.end(),
            [element](const ladder::ElementLayout& e) { return e.element == element; });
        const auto output =
            std::find_if(elements.begin(), elements.end(),
                         [](const ladder::ElementLayout& e) { return e.output >= 0; });
        m_selectedElement =
            static_cast<std::size_t>((found != elements.end() ? found : output) - elements.begin());
    }
    if (before != m_selectedRung || beforeElement != m_selectedElement) {
        ensureSelectionVisible();
        viewport()->update();
        Q_EMIT selectionChanged();
    }
}

void Pl110LadderView::moveSelection(int columns, int rungs) {
    const ladder::ElementLayout* current = selectedElement();
    if (!current)
        return;
    if (rungs != 0) {
        const int target = std::clamp(m_selectedRung + rungs, 1, rungCount());
        // The element nearest the same column in the rung above or below.
        const auto& elements = m_rungs[static_cast<std::size_t>(target - 1)].layout.elements;
        const auto nearest = std::min_element(
            elements.begin(), elements.end(),
            [column = current->column](const ladder::ElementLayout& a,
                                       const ladder::ElementLayout& b) {
                return std::abs(a.column - column) + a.row < std::abs(b.column - column) + b.row;
            });
        select(target, nearest == elements.end() ? 0 : nearest->element);
        return;
    }
    // Left to right, top to bottom.
    const auto& elements = m_rungs[static_cast<std::size_t>(m_selectedRung - 1)].layout.elements;
    std::vector<const ladder::ElementLayout*> order;
    for (const ladder::ElementLayout& element : elements)
        order.push_back(&element);
    std::sort(order.begin(), order.end(), [](const auto* a, const auto* b) {
        return std::pair(a->column, a->row) < std::pair(b->column, b->row);
    });
    const auto at = std::find(order.begin(), order.end(), current) - order.begin();
    const auto next =
        std::clamp<std::ptrdiff_t>(at + columns, 0, static_cast<std::ptrdiff_t>(order.size()) - 1);
    select(m_selectedRung, order[static_cast<std::size_t>(next)]->element);
}

void Pl110LadderView::ensureSelectionVisible() {
    const ladder::ElementLayout* element = selectedElement();
    if (!element)
        return;
    const PlacedRung& rung = m_rungs[static_cast<std::size_t>(m_selectedRung - 1)];
    const QRectF cell = element->cell.translated(0, rung.top);
    QScrollBar* vertical = verticalScrollBar();
    const int height = viewport()->height();
    if (rung.top < vertical->value() ||
        rung.top + rung.layout.size.height() > vertical->value() + height)
        vertical->setValue(static_cast<int>(std::min(rung.top, cell.bottom() - height + 8)));
    QScrollBar* horizontal = horizontalScrollBar();
    if (cell.left() < horizontal->value() ||
        cell.right() > horizontal->value() + viewport()->width())
        horizontal->setValue(static_cast<int>(cell.left() - 16));
}

int Pl110LadderView::elementAt(const PlacedRung& rung, const QPoint& point) const {
    const QPointF inRung = contentPoint(point) - QPointF(0, rung.top);
    for (std::size_t i = 0; i < rung.layout.elements.size(); ++i)
        if (rung.layout.elements[i].cell.contains(inRung))
            return static_cast<int>(i);
    return -1;
}

void Pl110LadderView::setPower(std::optional<render::PowerSnapshot> power) {
    m_power = std::move(power);
    viewport()->update();
}

bool Pl110LadderView::showRung(int number) {
    if (number < 1 || number > rungCount())
        return false;
    select(number);
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
    const PlacedRung* rung = rungAt(contentPoint(point));
    const int index = rung ? elementAt(*rung, point) : -1;
    if (index < 0)
        return {};
    const ladder::ElementLayout& element = rung->layout.elements[static_cast<std::size_t>(index)];
    return element.shape != ladder::Shape::Box ? element.address : QString();
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
        painter.drawText(
            QRectF(kHeadingIndent - dx, heading.top - dy, m_size.width(), kHeadingHeight),
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
        if (&rung - m_rungs.data() + 1 == m_selectedRung) {
            if (const ladder::ElementLayout* selected = selectedElement()) {
                painter.setPen(QPen(m_selectionColour, hasFocus() ? 2.5 : 1.5,
                                    hasFocus() ? Qt::SolidLine : Qt::DashLine));
                painter.setBrush(Qt::NoBrush);
                painter.drawRoundedRect(selected->cell.adjusted(3, 3, -3, -3), 4, 4);
            }
        }
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
    const QPoint point = event->position().toPoint();
    if (const PlacedRung* rung = rungAt(contentPoint(point))) {
        const int element = elementAt(*rung, point);
        select(static_cast<int>(rung - m_rungs.data()) + 1,
               element < 0 ? 0 : rung->layout.elements[static_cast<std::size_t>(element)].element);
    }
    if (event->button() == Qt::LeftButton)
        if (const QString address = addressAt(point); !address.isEmpty())
            Q_EMIT operandClicked(address);
    QAbstractScrollArea::mousePressEvent(event);
}

void Pl110LadderView::mouseDoubleClickEvent(QMouseEvent* event) {
    if (rungAt(contentPoint(event->position().toPoint())))
        Q_EMIT editRequested();
}

void Pl110LadderView::contextMenuEvent(QContextMenuEvent* event) {
    if (event->reason() == QContextMenuEvent::Mouse) {
        if (const QString address = addressAt(event->pos()); !address.isEmpty())
            Q_EMIT operandMenuRequested(address, event->globalPos());
        return;
    }
    // From the keyboard: the selected element's menu, where it stands.
    if (const ladder::ElementLayout* element = selectedElement();
        element && element->shape != ladder::Shape::Box && !element->address.isEmpty()) {
        const PlacedRung& rung = m_rungs[static_cast<std::size_t>(m_selectedRung - 1)];
        const QPointF corner =
            element->cell.bottomLeft() + QPointF(0, rung.top) -
            QPointF(horizontalScrollBar()->value(), verticalScrollBar()->value());
        Q_EMIT operandMenuRequested(element->address, viewport()->mapToGlobal(corner.toPoint()));
    }
}

void Pl110LadderView::focusInEvent(QFocusEvent* event) {
    QAbstractScrollArea::focusInEvent(event);
    viewport()->update();
}

void Pl110LadderView::focusOutEvent(QFocusEvent* event) {
    QAbstractScrollArea::focusOutEvent(event);
    viewport()->update();
}

void Pl110LadderView::changeEvent(QEvent* event) {
    QAbstractScrollArea::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        updateStyle();
}

void Pl110LadderView::updateStyle() {
    const LadderDrawing drawing = drawingFor(palette());
    m_style = drawing.style;
    m_selectionColour = drawing.selection;
    viewport()->update();
}

} // namespace rs::ui
