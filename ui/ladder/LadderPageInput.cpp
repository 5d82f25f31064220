// SPDX-License-Identifier: GPL-3.0-or-later
// What the states of a ladder page's tools do with the mouse and the keys:
// the page's side of IdleTool, DragTool and LiveTool.
#include "LadderPage.h"

#include "DragTool.h"
#include "LadderActions.h"
#include "LadderTool.h"
#include "LadderView.h"
#include "NetworkItem.h"
#include "StepHeaderItem.h"
#include "document/ProjectDocument.h"

#include <QDrag>
#include <QMenu>
#include <QMimeData>

#include <algorithm>

namespace rs::ui {

bool LadderPage::toggleCollapseAt(const QPointF& scenePosition) {
    NetworkItem* item = itemAt(scenePosition);
    if (!item || !item->inCollapseBox(item->mapFromScene(scenePosition)))
        return false;
    toggleCollapsed(item->step(), item->index());
    return true;
}

bool LadderPage::toggleOptionAt(const QPointF& scenePosition) {
    NetworkItem* item = itemAt(scenePosition);
    if (!item || !item->option() ||
        !item->optionBox().adjusted(-4, -4, 4, 4).contains(item->mapFromScene(scenePosition)))
        return false;
    setCursor({item->step(), item->index(), std::nullopt, std::nullopt, -1});
    toggleConfigOption(item->step(), item->index());
    return true;
}

void LadderPage::select(const QPointF& scenePosition, Qt::MouseButton button,
                        Qt::KeyboardModifiers modifiers) {
    const LadderCursor at = cursorAt(scenePosition);
    if (button == Qt::LeftButton && (modifiers & Qt::ControlModifier) && at.valid()) {
        const auto key = std::make_pair(at.step, at.network);
        if (!m_drawing.marked.erase(key))
            m_drawing.marked.insert(key);
    } else if (button == Qt::LeftButton && (modifiers & Qt::ShiftModifier) && at.valid() &&
               m_drawing.cursor.valid() && at.step == m_drawing.cursor.step) {
        const auto [low, high] = std::minmax(at.network, m_drawing.cursor.network);
        for (int n = low; n <= high; ++n)
            m_drawing.marked.insert({at.step, n});
    } else if (button == Qt::LeftButton ||
               (button == Qt::RightButton && !m_drawing.marked.count({at.step, at.network}))) {
        m_drawing.marked.clear();
    }
    setCursor(at);
}

void LadderPage::openAt(const QPointF& scenePosition) {
    for (std::size_t s = 0; s < m_headers.size(); ++s)
        if (m_headers[s]->isVisible() &&
            m_headers[s]->sceneBoundingRect().contains(scenePosition)) {
            editStepComment(static_cast<int>(s));
            return;
        }
    NetworkItem* item = itemAt(scenePosition);
    if (!item)
        return;
    const LadderCursor at = cursorAt(scenePosition);
    setCursor(at);
    if (item->option())
        editConfigOption(at.step, at.network);
    else if (item->network().block)
        editBlockPins(at.step, at.network);
    else if (at.wholeNetwork())
        editNetworkComment();
    else
        editProperties();
}

void LadderPage::openSelected() {
    if (NetworkItem* item = networkItem(m_drawing.cursor.step, m_drawing.cursor.network);
        item && item->option())
        editConfigOption(item->step(), item->index());
    else
        editProperties();
}

void LadderPage::showEditMenu(const QPoint& globalPosition) {
    const LadderActions& a = *m_actions;
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("ladderMenu"));
    menu.addActions({a.newNetwork, a.insertBlock, a.newConfigOption, a.cutNetworks, a.copyNetworks,
                     a.pasteNetworks, a.deleteNetworks});
    menu.addSeparator();
    if (cursorElement())
        menu.addActions({a.properties, a.deleteSelection});
    if (blockStatus(m_drawing.cursor.step, m_drawing.cursor.network))
        menu.addActions({a.properties, a.updateBlock, a.blockDocumentation});
    menu.addActions({a.networkComment, a.editNetwork});
    if (m_sequence > 0)
        menu.addAction(a.newStep);
    menu.addAction(a.newSequence);
    menu.exec(globalPosition);
}

// ----- drag and drop

void LadderPage::dragFrom(const QPointF& from, LadderTool& resume) {
    const LadderCursor at = cursorAt(from);
    if (!at.node)
        return;
    setCursor(at);
    m_dragTool->run(from, resume);
}

void LadderPage::dragElement(const QPointF& from) {
    const LadderCursor at = cursorAt(from);
    const QByteArray payload = QStringLiteral("%1 %2 %3 %4")
                                   .arg(reinterpret_cast<quintptr>(this))
                                   .arg(at.step)
                                   .arg(at.network)
                                   .arg(static_cast<qulonglong>(at.node->item))
                                   .toUtf8() +
                               [&] {
                                   QByteArray path;
                                   for (std::size_t i : at.node->node)
                                       path += ' ' + QByteArray::number(static_cast<qulonglong>(i));
                                   return path;
                               }();
    auto* data = new QMimeData;
    data->setData(QLatin1String(kElementMimeType), payload);
    auto* drag = new QDrag(m_view);
    drag->setMimeData(data);
    drag->exec(Qt::MoveAction);
}

void LadderPage::dropElement(const QPointF& scenePosition, const QByteArray& payload) {
    const QList<QByteArray> words = payload.split(' ');
    if (words.size() < 4 || words[0].toULongLong() != reinterpret_cast<quintptr>(this))
        return;
    const int step = words[1].toInt();
    const int network = words[2].toInt();
    ladder::ElementPath node{static_cast<std::size_t>(words[3].toULongLong()), {}};
    for (int i = 4; i < words.size(); ++i)
        node.node.push_back(static_cast<std::size_t>(words[i].toULongLong()));
    const LadderCursor target = cursorAt(scenePosition);
    if (!target.node)
        return;
    NetworkItem* item = networkItem(target.step, target.network);
    const int index = item->elementAt(item->mapFromScene(scenePosition));
    const ladder::Side side =
        index >= 0 && item->mapFromScene(scenePosition).x() <
                          item->elementRect(item->layout().elements[index]).center().x()
            ? ladder::Side::Before
            : ladder::Side::After;
    moveElement({step, network, node, std::nullopt, -1}, target, side);
}

// ----- live

void LadderPage::pointAt(const QPointF& scenePosition) {
    m_drawing.cursor = cursorAt(scenePosition);
    explainOutput();
    repaintItems();
}

void LadderPage::reportOperand() {
    if (const ladder::ElementLayout* element = cursorElement();
        element && !element->address.isEmpty())
        emit operandClicked(element->address);
}

void LadderPage::reportOperandMenu(std::optional<QPoint> globalPosition) {
    const ladder::ElementLayout* element = cursorElement();
    if (!element || element->address.isEmpty())
        return;
    if (!globalPosition) {
        NetworkItem* item = networkItem(m_drawing.cursor.step, m_drawing.cursor.network);
        const QPointF centre = item->mapToScene(item->elementRect(*element).center());
        globalPosition = m_view->viewport()->mapToGlobal(m_view->mapFromScene(centre));
    }
    emit operandMenuRequested(element->address, *globalPosition);
}

} // namespace rs::ui
