// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderActions.h"

#include "ElementKind.h"

#include <QAction>
#include <QActionGroup>
#include <QKeySequence>
#include <QWidget>

namespace rs::ui {

namespace {

QAction* made(QWidget* page, const char* name, const QString& text, const QString& tip = {}) {
    auto* action = new QAction(text, page);
    action->setObjectName(QLatin1String(name));
    if (!tip.isEmpty())
        action->setToolTip(tip);
    return action;
}

} // namespace

QString LadderActions::keyOf(const QAction* action) {
    return action->shortcut().toString(QKeySequence::NativeText);
}

LadderActions::LadderActions(QWidget* page) {
    // An action with keys answers them when the view receives them (LadderView
    // asks its key actions), and its tooltip names its first key. The shortcut
    // context is the action's own widget, which never has the focus: matched
    // by the focus widget, Enter or a letter would reach the view while one of
    // the page's dialogs opens and has not taken the focus yet.
    auto keyed = [this](QAction* action, const QList<QKeySequence>& keys) {
        action->setShortcuts(keys);
        action->setShortcutContext(Qt::WidgetShortcut);
        viewKeys.push_back(action);
        if (!action->toolTip().isEmpty() && action->toolTip() != action->iconText())
            action->setToolTip(tr("%1 (key %2)").arg(action->toolTip(), keyOf(action)));
        return action;
    };

    showText = made(page, "ladderTextAction", tr("Text"), tr("Show this code as text"));

    placements = new QActionGroup(page);
    placeAfter = keyed(
        made(page, "placeAfterAction", tr("After"), tr("Insert in series after the selection")),
        {QKeySequence(Qt::Key_BracketRight)});
    placeBefore = keyed(
        made(page, "placeBeforeAction", tr("Before"), tr("Insert in series before the selection")),
        {QKeySequence(Qt::Key_BracketLeft)});
    placeParallel = keyed(made(page, "placeParallelAction", tr("Parallel"),
                               tr("Insert in a parallel branch around the selection")),
                          {QKeySequence(Qt::Key_Backslash), QKeySequence(Qt::Key_Bar)});
    for (QAction* action : {placeAfter, placeBefore, placeParallel}) {
        action->setCheckable(true);
        placements->addAction(action);
    }
    placeAfter->setChecked(true);

    for (const ElementKindInfo& info : ladder::elementKinds()) {
        QAction* action = new QAction(QString::fromLatin1(info.picture), page);
        action->setObjectName(QStringLiteral("insert%1Action").arg(static_cast<int>(info.kind)));
        action->setToolTip(ElementKinds::name(info.kind));
        insert.emplace_back(info.kind,
                            keyed(action, {QKeySequence(QLatin1String(info.insertKey))}));
    }

    deleteSelection =
        keyed(made(page, "ladderDeleteAction", tr("&Delete"), tr("Delete the selected element")),
              {QKeySequence(Qt::Key_Delete), QKeySequence(Qt::Key_Backspace)});
    newNetwork = keyed(made(page, "newNetworkAction", tr("&New Network"),
                            tr("A new network below the selected one")),
                       {QKeySequence(Qt::Key_Insert)});
    insertBlock = keyed(made(page, "insertBlockAction", tr("&Function..."),
                             tr("A new network holding a function block of the libraries")),
                        {QKeySequence(Qt::SHIFT | Qt::Key_F)});
    insertBlock->setIconText(tr("F"));
    expandAll =
        made(page, "expandAllAction", tr("Expand All"), tr("Show the rungs of every network"));
    collapseAll = made(page, "collapseAllAction", tr("Collapse All"),
                       tr("Show only the comments of the networks"));
    editNetwork = keyed(made(page, "editNetworkAction", tr("&Edit Network"),
                             tr("Gather the next edits of this network until Update")),
                        {QKeySequence(Qt::Key_E)});
    updateNetwork = keyed(made(page, "updateNetworkAction", tr("Update"),
                               tr("Keep the edits of the network as one step")),
                          {QKeySequence(Qt::Key_F3)});
    undoNetwork = keyed(
        made(page, "undoNetworkAction", tr("Undo Network"), tr("Drop the edits of the network")),
        {QKeySequence(Qt::Key_F2)});

    zoomIn = made(page, "zoomInAction", tr("Zoom In"), tr("Zoom in"));
    zoomOut = made(page, "zoomOutAction", tr("Zoom Out"), tr("Zoom out"));
    // Short on the tool bar, which must show every command at 1,280 px.
    zoomIn->setIconText(QStringLiteral("+"));
    zoomOut->setIconText(QStringLiteral("\u2212"));
    expandAll->setIconText(tr("Expand"));
    collapseAll->setIconText(tr("Collapse"));
    // The same words as the menus' in English; a language with longer ones
    // can say them shorter here.
    editNetwork->setIconText(tr("Edit Network", "tool bar"));
    undoNetwork->setIconText(tr("Undo Network", "tool bar"));
    newNetwork->setIconText(tr("New Network", "tool bar"));
    zoomReset = made(page, "zoomResetAction", tr("100%"), tr("Actual size"));
    const std::pair<QAction*, QList<QKeySequence>> zooms[] = {
        {zoomIn, {QKeySequence::ZoomIn, QKeySequence(Qt::CTRL | Qt::Key_Equal)}},
        {zoomOut, QKeySequence::keyBindings(QKeySequence::ZoomOut)},
        {zoomReset, {QKeySequence(Qt::CTRL | Qt::Key_0)}},
    };
    // Zooming answers anywhere on the page.
    for (const auto& [action, keys] : zooms) {
        action->setShortcuts(keys);
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        action->setToolTip(tr("%1 (key %2)").arg(action->toolTip(), keyOf(action)));
        page->addAction(action);
    }

    print = made(page, "printLadderAction", tr("Print..."), tr("Print the networks of this page"));
    exportPdf =
        made(page, "exportPdfAction", tr("PDF..."), tr("Export the networks of this page as PDF"));

    properties = keyed(made(page, "propertiesAction", tr("P&roperties...")),
                       {QKeySequence(Qt::Key_Return), QKeySequence(Qt::Key_Enter)});
    toggle = keyed(made(page, "toggleAction", tr("&Toggle")), {QKeySequence(Qt::Key_Space)});
    operandMenu = keyed(made(page, "operandMenuAction", tr("&Force...")),
                        {QKeySequence(Qt::Key_Menu), QKeySequence(Qt::SHIFT | Qt::Key_F10)});
    moveLeft = keyed(made(page, "moveLeftAction", tr("Move Left")), {QKeySequence(Qt::Key_Left)});
    moveRight =
        keyed(made(page, "moveRightAction", tr("Move Right")), {QKeySequence(Qt::Key_Right)});
    moveUp = keyed(made(page, "moveUpAction", tr("Move Up")), {QKeySequence(Qt::Key_Up)});
    moveDown = keyed(made(page, "moveDownAction", tr("Move Down")), {QKeySequence(Qt::Key_Down)});
    selectGroup = keyed(made(page, "selectGroupAction", tr("Select Enclosing Group")),
                        {QKeySequence(Qt::ALT | Qt::Key_Up)});
    selectNetwork = keyed(made(page, "selectNetworkAction", tr("Select Network")),
                          {QKeySequence(Qt::Key_Home)});

    newConfigOption = made(page, "newConfigOptionAction", tr("New &Config Option..."));
    updateBlock = made(page, "updateBlockAction", tr("&Update Block"));
    makeBlock = made(page, "makeBlockAction", tr("&Make Block..."));
    blockDocumentation = made(page, "blockDocumentationAction", tr("&Block Documentation..."));
    cutNetworks = made(page, "cutNetworksAction", tr("Cu&t Network(s)"));
    copyNetworks = made(page, "copyNetworksAction", tr("&Copy Network(s)"));
    pasteNetworks = made(page, "pasteNetworksAction", tr("&Paste Network(s)"));
    deleteNetworks = made(page, "deleteNetworksAction", tr("&Delete Network(s)"));
    networkComment = made(page, "networkCommentAction", tr("Network Co&mment..."));
    newStep = made(page, "newStepAction", tr("New &Step"));
    newSequence = made(page, "newSequenceAction", tr("New Se&quence..."));
}

std::vector<QAction*> LadderActions::elementBar() const {
    std::vector<QAction*> bar;
    for (const auto& [kind, action] : insert) {
        bar.push_back(action);
        if (kind == ElementKind::Comparison)
            bar.insert(bar.end(), {insertBlock, nullptr}); // a block is a box too
    }
    bar.insert(bar.end(), {nullptr, deleteSelection, newNetwork});
    return bar;
}

std::vector<QAction*> LadderActions::networkBar() const {
    return {showText,  nullptr,     placeAfter,    placeBefore, placeParallel,
            nullptr,   editNetwork, updateNetwork, undoNetwork, nullptr,
            expandAll, collapseAll, nullptr,       zoomIn,      zoomOut,
            zoomReset, nullptr,     print,         exportPdf};
}

std::vector<QAction*> LadderActions::viewing() const {
    return {showText,  expandAll, collapseAll, zoomIn, zoomOut,  zoomReset,   print,
            exportPdf, moveLeft,  moveRight,   moveUp, moveDown, selectGroup, selectNetwork};
}

} // namespace rs::ui
