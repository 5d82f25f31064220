// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderDrawing.h"

#include <QGraphicsItem>

namespace rs::ui {

// The heading of a step on a sequence page: "Step 2 (S0.1_2)" and the step's
// comment; while simulating, the active step is marked.
class StepHeaderItem : public QGraphicsItem {
public:
    static constexpr qreal kHeight = 30;

    StepHeaderItem(const LadderDrawing* drawing, int sequence, int step, QString text);

    void setText(int step, const QString& text);
    void setWidth(qreal width);
    int stepNumber() const { return m_stepNumber; }

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
    const LadderDrawing* m_drawing;
    int m_sequence;
    int m_stepNumber;
    QString m_text;
    qreal m_width = 600;
};

} // namespace rs::ui
