// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ElementKind.h"

#include <QCoreApplication>
#include <QString>

#include <utility>
#include <vector>

class QAction;
class QActionGroup;
class QWidget;

namespace rs::ui {

// Every command of a ladder page as an action, each with its keys, made once
// here: the toolbar, the context menu and the view's keys are these actions,
// and a tooltip names the key its action has. The page connects them.
class LadderActions {
    Q_DECLARE_TR_FUNCTIONS(LadderActions)
public:
    // The actions are children of `page`.
    explicit LadderActions(QWidget* page);

    QAction* showText;
    QActionGroup* placements;
    QAction* placeAfter;
    QAction* placeBefore;
    QAction* placeParallel;
    std::vector<std::pair<ladder::ElementKind, QAction*>> insert; // in the vocabulary's order
    QAction* deleteSelection;
    QAction* newNetwork;
    QAction* insertBlock; // New Network → Function…, the F button
    QAction* expandAll;
    QAction* collapseAll;
    QAction* editNetwork;
    QAction* updateNetwork;
    QAction* undoNetwork;
    QAction* zoomIn;
    QAction* zoomOut;
    QAction* zoomReset;
    QAction* print;
    QAction* exportPdf;

    // Keys of the view without a toolbar button.
    QAction* properties;  // Enter: the element's or option's dialog
    QAction* toggle;      // Space: an option's check box, or live the input under the cursor
    QAction* operandMenu; // live: the forcing menu of the element under the cursor
    QAction* moveLeft;
    QAction* moveRight;
    QAction* moveUp;
    QAction* moveDown;
    QAction* selectGroup;   // the group around the selected node
    QAction* selectNetwork; // the network of the selection as a whole

    // The context menu's commands without keys.
    QAction* newConfigOption;
    QAction* updateBlock;
    QAction* blockDocumentation;
    QAction* makeBlock;
    QAction* cutNetworks;
    QAction* copyNetworks;
    QAction* pasteNetworks;
    QAction* deleteNetworks;
    QAction* networkComment;
    QAction* newStep;
    QAction* newSequence;

    // The actions whose keys the view answers (all with keys but zooming,
    // which answers anywhere on the page).
    std::vector<QAction*> viewKeys;

    // The page's two tool bars, in order (nullptr a separator), so that every
    // command shows at 1,280 px and at 1,024 px the contacts, boxes and the
    // coil, S and R still do (issue 17): the network and view commands, and
    // the elements to insert with Delete and New Network.
    std::vector<QAction*> elementBar() const;
    std::vector<QAction*> networkBar() const;
    // The actions that read the page: they stay enabled while simulating.
    std::vector<QAction*> viewing() const;
    // The text that names an action's first key, as menus show it ("Del").
    static QString keyOf(const QAction* action);
};

} // namespace rs::ui
