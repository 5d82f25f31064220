// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkPainter.h"

#include "ladder/ElementVocabulary.h"
#include "sim/Conduction.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <optional>

namespace rs::render {

namespace {

using ladder::ElementKind;
using ladder::ElementLayout;
using ladder::Shape;

constexpr qreal kBubbleRadius = 4; // the circle that negates a box's output
constexpr qreal kCountingBar = 5;  // along the foot of a timer that is counting

// A font with its metrics, made once per network rather than once per label.
struct TextFont {
    explicit TextFont(const QFont& f) : font(f), metrics(f) {}
    QFont font;
    QFontMetricsF metrics;
};

class Painter {
public:
    Painter(QPainter& painter, const ladder::NetworkLayout& layout, const LadderStyle& style,
            const PowerSnapshot* power)
        : m_painter(painter), m_layout(layout), m_style(style), m_power(power),
          m_symbolFont(style.font(style.textPixelSize, true)),
          m_nameFont(style.font(style.labelPixelSize, true)),
          m_addressFont(style.font(style.labelPixelSize)),
          m_titleFont(style.font(style.titlePixelSize, true)),
          m_commentFont(style.font(style.titlePixelSize)),
          m_asideFont(style.font(style.labelPixelSize, false, true)) {}

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
        if (m_layout.block)
            drawBlock(*m_layout.block);
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

    // The symbol's outline says whether power leaves it (the wire's colour
    // and weight); its fill says the element's own state, whatever power
    // reaches it: a closed contact, a true comparison or timer, an output
    // whose variable is 1 is filled; a counting timer has a bar along its
    // foot.
    void drawElement(const ElementLayout& e) {
        const bool powered = m_power && m_power->conducts(e.statement, e.element);
        const std::uint8_t state = m_power ? m_power->state(e.statement, e.element) : 0;
        const bool closed = (state & sim::ElementState::Closed) != 0;
        m_painter.setPen(m_style.wirePen(powered));
        m_painter.setBrush(closed                   ? QBrush(m_style.closedFill)
                           : m_style.body.isValid() ? QBrush(m_style.body)
                                                    : QBrush(m_style.background));
        const QRectF& r = e.symbolRect;
        const QString& mark = e.mark;
        const QColor& ink = closed ? m_style.closedInk : m_style.ink;
        switch (e.shape) {
        case Shape::Contact:
            // An inverted edge is written as the text writes it, "/P": a slash
            // through the letter would hide it.
            if (mark == QLatin1String("/"))
                contact(r, {}, true, ink);
            else
                contact(r, mark, false, ink);
            break;
        case Shape::Coil:
            coil(r, mark, ink);
            break;
        case Shape::Box:
            box(r, e.text, e.negated, ink, (state & sim::ElementState::Running) != 0);
            break;
        }
        label(e.nameRect, e.name, m_style.nameInk, m_nameFont);
        label(e.addressRect, e.address, m_style.addressInk, m_addressFont);
    }

    // The live value of a pin's variable; nothing without a snapshot or a variable.
    std::optional<std::int64_t> valueOf(const ladder::PinLayout& pin) const {
        if (!m_power || !pin.address)
            return std::nullopt;
        const auto found = m_power->values.find(*pin.address);
        if (found == m_power->values.end())
            return std::nullopt;
        return found->second;
    }

    void drawBlock(const ladder::BlockLayout& block) {
        m_painter.setPen(m_style.wirePen(false));
        m_painter.setBrush(m_style.background);
        m_painter.drawRect(block.box);
        m_painter.setPen(m_style.ink);
        drawText(m_symbolFont, block.typeRect, Qt::AlignCenter, block.type, Qt::ElideRight);
        for (const auto& pin : block.pins)
            drawPin(pin);
    }

    // A pin: its name inside the box, its wire, and its operand with the
    // live value; a bit pin's wire is powered as a contact's is.
    void drawPin(const ladder::PinLayout& pin) {
        const bool in = pin.direction == blocks::PinDirection::In;
        const std::optional<std::int64_t> value = valueOf(pin);
        const bool bit = pin.kind == blocks::PinKind::Bit;
        const bool powered = bit && value && *value != 0;
        m_painter.setPen(m_style.wirePen(powered));
        if (!pin.stub.isNull())
            m_painter.drawLine(pin.stub);
        if (pin.power && !pin.contactRect.isEmpty()) {
            m_painter.setPen(m_style.wirePen(powered));
            m_painter.setBrush(powered ? QBrush(m_style.poweredFill) : QBrush(m_style.background));
            contact(pin.contactRect, {}, false, m_style.ink);
        }
        m_painter.setPen(m_style.ink);
        drawText(m_addressFont, pin.pinRect,
                 (in ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter, pin.pin, Qt::ElideRight);
        const int side = pin.power ? Qt::AlignHCenter : (in ? Qt::AlignRight : Qt::AlignLeft);
        if (!pin.name.isEmpty()) {
            m_painter.setPen(m_style.nameInk);
            drawText(m_nameFont, pin.nameRect, side | Qt::AlignBottom, pin.name, Qt::ElideMiddle);
        }
        QString operand = pin.operand;
        if (value && !bit)
            operand += QStringLiteral(" = %1").arg(*value);
        m_painter.setPen(pin.missing ? m_style.ink : m_style.addressInk);
        drawText(pin.missing ? m_nameFont : m_addressFont, pin.operandRect, side | Qt::AlignTop,
                 operand, Qt::ElideMiddle);
    }

    // -| |-, with a slash when normally closed, or the edge's letter; the
    // painter's brush fills it, the letter and slash are in `ink`.
    void contact(const QRectF& r, const QString& letter, bool slashed, const QColor& ink) {
        const QPen pen = m_painter.pen();
        m_painter.setPen(Qt::NoPen);
        m_painter.drawRect(r);
        m_painter.setPen(pen);
        m_painter.drawLine(r.topLeft(), r.bottomLeft());
        m_painter.drawLine(r.topRight(), r.bottomRight());
        if (!letter.isEmpty())
            symbolText(r, letter, ink);
        if (slashed) {
            QPen slash = pen;
            slash.setColor(ink == m_style.ink ? pen.color() : ink);
            m_painter.setPen(slash);
            m_painter.drawLine(QPointF(r.left() + 2, r.bottom() - 2),
                               QPointF(r.right() - 2, r.top() + 2));
        }
    }

    // -( )-, with the letter of what the coil does.
    void coil(const QRectF& r, const QString& letter, const QColor& ink) {
        const QPen pen = m_painter.pen();
        m_painter.setPen(Qt::NoPen);
        m_painter.drawEllipse(r);
        m_painter.setPen(pen);
        m_painter.drawArc(r, 120 * 16, 120 * 16);
        m_painter.drawArc(r, -60 * 16, 120 * 16);
        if (!letter.isEmpty())
            symbolText(r, letter, ink);
    }

    void box(const QRectF& r, const QString& text, bool negated, const QColor& ink, bool counting) {
        m_painter.drawRect(r);
        if (counting) {
            const qreal width = m_painter.pen().widthF();
            m_painter.fillRect(QRectF(r.left() + width / 2, r.bottom() - width / 2 - kCountingBar,
                                      r.width() - width, kCountingBar),
                               m_style.closedFill);
        }
        if (negated) {
            m_painter.setBrush(m_style.background); // the bubble negates what the box says
            m_painter.drawEllipse(QPointF(r.right() + kBubbleRadius, r.center().y()), kBubbleRadius,
                                  kBubbleRadius);
        }
        symbolText(r.adjusted(3, 0, -3, 0), text, ink);
    }

    void symbolText(const QRectF& r, const QString& text, const QColor& ink) {
        m_painter.setPen(ink);
        drawText(m_symbolFont, r, Qt::AlignCenter, text, Qt::ElideRight);
    }

    void label(const QRectF& r, const QString& text, const QColor& colour, const TextFont& font) {
        if (text.isEmpty())
            return;
        m_painter.setPen(colour);
        drawText(font, r, Qt::AlignCenter, text, Qt::ElideMiddle);
    }

    void drawText(const ladder::TextLayout& t) {
        using Role = ladder::TextLayout::Role;
        const bool aside = t.role == Role::Note || t.role == Role::OutputComment;
        const TextFont& font = t.role == Role::Title     ? m_titleFont
                               : t.role == Role::Comment ? m_commentFont
                                                         : m_asideFont;
        m_painter.setPen(aside ? m_style.commentInk : m_style.ink);
        // The layout sizes text from an average character width; a line may
        // use the room up to the picture's right edge before it is shortened.
        QRectF room = t.rect;
        room.setRight(std::max(t.rect.right(), m_layout.size.width() - m_layout.metrics.margin));
        drawText(font, room, Qt::AlignLeft | Qt::AlignVCenter, t.text, Qt::ElideRight);
    }

    // Text that does not fit is shortened with an ellipsis, never clipped.
    void drawText(const TextFont& font, const QRectF& r, int alignment, const QString& text,
                  Qt::TextElideMode elide) {
        m_painter.setFont(font.font);
        m_painter.drawText(r, alignment, font.metrics.elidedText(text, elide, r.width()));
    }

    QPainter& m_painter;
    const ladder::NetworkLayout& m_layout;
    const LadderStyle& m_style;
    const PowerSnapshot* m_power;
    const TextFont m_symbolFont;
    const TextFont m_nameFont;
    const TextFont m_addressFont;
    const TextFont m_titleFont;
    const TextFont m_commentFont;
    const TextFont m_asideFont;
};

} // namespace

void paintNetwork(QPainter& painter, const ladder::NetworkLayout& layout, const LadderStyle& style,
                  const PowerSnapshot* power) {
    Painter(painter, layout, style, power).run();
}

} // namespace rs::render
