#include "NetworkPainter.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>

namespace rs::render {

namespace {

using ladder::ElementLayout;
using ladder::Symbol;

constexpr qreal kBubbleRadius = 4; // the circle that negates a box's output

class Painter {
public:
    Painter(QPainter& painter, const ladder::NetworkLayout& layout, const LadderStyle& style,
            const PowerSnapshot* power)
        : m_painter(painter), m_layout(layout), m_style(style), m_power(power) {}

    void run() {
        m_painter.save();
        m_painter.setRenderHint(QPainter::Antialiasing);
        m_painter.setRenderHint(QPainter::TextAntialiasing);
        m_painter.fillRect(QRectF(QPointF(0, 0), m_layout.size), m_style.background);
        // Conducting wires go on top, so a powered path stays whole where it
        // meets unpowered ones.
        for (bool powered : {false, true})
            for (const auto& wire : m_layout.wires)
                if (isPowered(wire.feed) == powered)
                    drawWire(wire, powered);
        for (const auto& element : m_layout.elements)
            drawElement(element);
        for (const auto& text : m_layout.texts)
            drawText(text);
        m_painter.restore();
    }

private:
    bool isPowered(const ladder::PowerFeed& feed) const { return m_power && m_power->powers(feed); }

    void drawWire(const ladder::WireLayout& wire, bool powered) {
        QPen pen = wire.rail ? m_style.railPen(powered) : m_style.wirePen(powered);
        // Vertical bars reach over the ends of the wires they join, so corners are closed.
        if (wire.line.x1() == wire.line.x2())
            pen.setCapStyle(Qt::SquareCap);
        m_painter.setPen(pen);
        m_painter.drawLine(wire.line);
    }

    void drawElement(const ElementLayout& e) {
        const bool powered = m_power && m_power->conducts(e.statement, e.element);
        QPen pen = m_style.wirePen(powered);
        m_painter.setPen(pen);
        m_painter.setBrush(powered ? QBrush(m_style.poweredFill) : QBrush(m_style.background));
        const QRectF& r = e.symbolRect;
        switch (e.symbol) {
        case Symbol::NormallyOpen:
            contact(r, {}, false);
            break;
        case Symbol::NormallyClosed:
            contact(r, {}, true);
            break;
        case Symbol::PositiveEdge:
            contact(r, QStringLiteral("P"), false);
            break;
        case Symbol::NegativeEdge:
            contact(r, QStringLiteral("N"), false);
            break;
        // An inverted edge is written as the text writes it: a slash through
        // the letter would hide it.
        case Symbol::NotPositiveEdge:
            contact(r, QStringLiteral("/P"), false);
            break;
        case Symbol::NotNegativeEdge:
            contact(r, QStringLiteral("/N"), false);
            break;
        case Symbol::Coil:
            coil(r, {});
            break;
        case Symbol::Set:
            coil(r, QStringLiteral("S"));
            break;
        case Symbol::Reset:
            coil(r, QStringLiteral("R"));
            break;
        case Symbol::Toggle:
            coil(r, QStringLiteral("T"));
            break;
        case Symbol::Jump:
            coil(r, QStringLiteral("J"));
            break;
        case Symbol::SequenceReset:
            coil(r, QStringLiteral("RS"));
            break;
        case Symbol::Timer:
        case Symbol::Comparison:
        case Symbol::Arithmetic:
            box(r, e.text, e.negated);
            break;
        }
        label(e.nameRect, e.name, m_style.nameInk, true);
        label(e.addressRect, e.address, m_style.addressInk, false);
    }

    // -| |-, with a slash when normally closed, or the edge's letter.
    void contact(const QRectF& r, const QString& letter, bool slashed) {
        const QPen pen = m_painter.pen();
        m_painter.setPen(Qt::NoPen);
        m_painter.drawRect(r);
        m_painter.setPen(pen);
        m_painter.drawLine(r.topLeft(), r.bottomLeft());
        m_painter.drawLine(r.topRight(), r.bottomRight());
        if (!letter.isEmpty())
            symbolText(r, letter);
        if (slashed)
            m_painter.drawLine(QPointF(r.left() + 2, r.bottom() - 2),
                               QPointF(r.right() - 2, r.top() + 2));
    }

    // -( )-, with the letter of what the coil does.
    void coil(const QRectF& r, const QString& letter) {
        const QPen pen = m_painter.pen();
        m_painter.setPen(Qt::NoPen);
        m_painter.drawEllipse(r);
        m_painter.setPen(pen);
        m_painter.drawArc(r, 120 * 16, 120 * 16);
        m_painter.drawArc(r, -60 * 16, 120 * 16);
        if (!letter.isEmpty())
            symbolText(r, letter);
    }

    void box(const QRectF& r, const QString& text, bool negated) {
        m_painter.drawRect(r);
        if (negated)
            m_painter.drawEllipse(QPointF(r.right() + kBubbleRadius, r.center().y()), kBubbleRadius,
                                  kBubbleRadius);
        symbolText(r.adjusted(3, 0, -3, 0), text);
    }

    void symbolText(const QRectF& r, const QString& text) {
        m_painter.setFont(m_style.font(m_style.textPixelSize, true));
        m_painter.setPen(m_style.ink);
        const QFontMetricsF metrics(m_painter.font());
        m_painter.drawText(r, Qt::AlignCenter, metrics.elidedText(text, Qt::ElideRight, r.width()));
    }

    void label(const QRectF& r, const QString& text, const QColor& colour, bool bold) {
        if (text.isEmpty())
            return;
        m_painter.setFont(m_style.font(m_style.labelPixelSize, bold));
        m_painter.setPen(colour);
        const QFontMetricsF metrics(m_painter.font());
        m_painter.drawText(r, Qt::AlignCenter,
                           metrics.elidedText(text, Qt::ElideMiddle, r.width()));
    }

    void drawText(const ladder::TextLayout& t) {
        using Role = ladder::TextLayout::Role;
        const bool title = t.role == Role::Title;
        const bool aside = t.role == Role::Note || t.role == Role::OutputComment;
        m_painter.setFont(m_style.font(title || t.role == Role::Comment ? m_style.titlePixelSize
                                                                        : m_style.labelPixelSize,
                                       title, aside));
        m_painter.setPen(aside ? m_style.commentInk : m_style.ink);
        // The layout sizes text from an average character width; a line may
        // use the room up to the picture's right edge before it is shortened.
        QRectF room = t.rect;
        room.setRight(std::max(t.rect.right(), m_layout.size.width() - m_layout.metrics.margin));
        const QFontMetricsF metrics(m_painter.font());
        m_painter.drawText(room, Qt::AlignLeft | Qt::AlignVCenter,
                           metrics.elidedText(t.text, Qt::ElideRight, room.width()));
    }

    QPainter& m_painter;
    const ladder::NetworkLayout& m_layout;
    const LadderStyle& m_style;
    const PowerSnapshot* m_power;
};

} // namespace

void paintNetwork(QPainter& painter, const ladder::NetworkLayout& layout, const LadderStyle& style,
                  const PowerSnapshot* power) {
    Painter(painter, layout, style, power).run();
}

} // namespace rs::render
