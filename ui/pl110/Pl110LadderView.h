// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "LadderStyle.h"
#include "PowerSnapshot.h"
#include "ladder/Layout.h"
#include "pl110/Program.h"
#endif

#include <QAbstractScrollArea>

#include <optional>
#include <vector>

namespace rs::ui {

// A PL110 program's rungs as ladder, INIT's then MAIN's, drawn by the
// renderer every target shares, with the simulator's power while it runs.
// A contact or coil can be clicked: the window decides what that does
// (sets an input, forces a variable); a double-click goes to the rung's
// line in the text.
class Pl110LadderView : public QAbstractScrollArea {
    Q_OBJECT
public:
    explicit Pl110LadderView(QWidget* parent = nullptr);

    void setProgram(const pl110::Program& program);
    // The power of the last scan, or nothing to draw the rungs at rest.
    void setPower(std::optional<render::PowerSnapshot> power);
    // Scrolls rung `number` (from 1) to the top; false when there is none.
    bool showRung(int number);
    int rungCount() const { return static_cast<int>(m_rungs.size()); }
    // The operand's address of the contact or coil at a point of the
    // viewport, or an empty string.
    QString addressAt(const QPoint& point) const;

Q_SIGNALS:
    void operandClicked(const QString& address);
    void operandMenuRequested(const QString& address, const QPoint& globalPosition);
    void lineActivated(int line);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    struct PlacedRung {
        ladder::NetworkLayout layout;
        qreal top = 0;
        int line = 0; // in the text, from 1
    };
    struct Heading {
        qreal top = 0;
        QString text;
    };
    void updateScrollBars();
    void updateStyle();
    QPointF contentPoint(const QPoint& viewportPoint) const;
    const PlacedRung* rungAt(const QPointF& point) const;

    std::vector<PlacedRung> m_rungs;
    std::vector<Heading> m_headings;
    QSizeF m_size;
    render::LadderStyle m_style;
    std::optional<render::PowerSnapshot> m_power;
};

} // namespace rs::ui
