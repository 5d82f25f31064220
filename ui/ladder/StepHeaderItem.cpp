// SPDX-License-Identifier: GPL-3.0-or-later
#include "StepHeaderItem.h"

#include <QPainter>

namespace rs::ui {

StepHeaderItem::StepHeaderItem(const LadderDrawing* drawing, int sequence, int step, QString text)
    : m_drawing(drawing), m_sequence(sequence), m_stepNumber(step), m_text(std::move(text)) {}

void StepHeaderItem::setText(int step, const QString& text) {
    m_stepNumber = step;
    m_text = text;
    update();
}

void StepHeaderItem::setWidth(qreal width) {
    if (width == m_width)
        return;
    prepareGeometryChange();
    m_width = width;
}

QRectF StepHeaderItem::boundingRect() const {
    return {0, 0, m_width, kHeight};
}

void StepHeaderItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
    const render::LadderStyle& style = m_drawing->style;
    const QRectF bounds = boundingRect();
    QColor band = style.ink;
    band.setAlpha(28);
    painter->fillRect(bounds, style.background);
    painter->fillRect(bounds.adjusted(0, 4, 0, 0), band);
    bool active = false;
    if (m_drawing->live)
        if (const auto found = m_drawing->live->activeSteps.find(m_sequence);
            found != m_drawing->live->activeSteps.end())
            active = found->second == m_stepNumber;
    if (active)
        painter->fillRect(QRectF(0, 4, 8, kHeight - 4), style.powered);
    painter->setPen(active ? style.powered : style.ink);
    painter->setFont(style.font(style.titlePixelSize + 1, true));
    painter->drawText(bounds.adjusted(14, 4, -8, 0), Qt::AlignVCenter | Qt::AlignLeft, m_text);
}

} // namespace rs::ui
