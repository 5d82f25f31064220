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
// One element (or a rung's output) is selected, by mouse or arrow keys; the
// window's edits act on it. A contact or coil can be clicked: the window
// decides what that does while simulating (sets an input, forces a
// variable); a double-click asks to edit what was clicked.
class Pl110LadderView : public QAbstractScrollArea {
    Q_OBJECT
public:
    explicit Pl110LadderView(QWidget* parent = nullptr);

    void setProgram(const pl110::Program& program);
    // The power of the last scan, or nothing to draw the rungs at rest.
    void setPower(std::optional<render::PowerSnapshot> power);
    // Selects rung `number` (from 1) and scrolls it to the top; false when
    // there is none.
    bool showRung(int number);
    int rungCount() const { return static_cast<int>(m_rungs.size()); }
    // The operand's address of the contact or coil at a point of the
    // viewport, or an empty string.
    QString addressAt(const QPoint& point) const;

    // The selected rung (from 1; 0 when there are none) and element (its
    // output when the rung as a whole is meant).
    int selectedRung() const { return m_selectedRung; }
    const ladder::ElementLayout* selectedElement() const;
    // The text line of the selected rung, 0 when none.
    int selectedLine() const;
    // Selects rung `number` and the element with that number in it (0 its
    // output), or its output when there is none.
    void select(int number, std::uint16_t element = 0);
    // Along the rung (columns) or to the rung above or below.
    void moveSelection(int columns, int rungs);

Q_SIGNALS:
    void operandClicked(const QString& address);
    void operandMenuRequested(const QString& address, const QPoint& globalPosition);
    void selectionChanged();
    void editRequested();

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void changeEvent(QEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

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
    // The element under a point of the viewport in the rung there, or -1.
    int elementAt(const PlacedRung& rung, const QPoint& point) const;
    void ensureSelectionVisible();

    std::vector<PlacedRung> m_rungs;
    std::vector<Heading> m_headings;
    QSizeF m_size;
    render::LadderStyle m_style;
    std::optional<render::PowerSnapshot> m_power;
    QColor m_selectionColour;
    int m_selectedRung = 0;
    std::size_t m_selectedElement = 0; // index in the rung's layout elements
};

} // namespace rs::ui
