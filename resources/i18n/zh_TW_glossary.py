#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Fills resources/i18n/tactus_zh_TW.ts from this glossary (Traditional Chinese,
Taiwan usage: 點字 braille, 點字印表機 embosser, 雙面點字 interpoint). Run after
`lupdate`; strings missing here stay unfinished and show in English."""
import sys
import xml.etree.ElementTree as ET

T = {
    "typing": "輸入",
    # Space in the braille pane, echoed as a typed chord is.
    "blank cell": "空方",
    # A message and its detail, a place and what is there: the full-width colon.
    "%1: %2": "%1：%2",
    # The profile's problems (core/profile/profile_problem.hpp), worded in the panel.
    "steps/s": "步/秒",
    "is %1, must be between %2 and %3": "為 %1，必須介於 %2 與 %3 之間",
    "is %1, must be above 0": "為 %1，必須大於 0",
    "is %1, must not exceed %2": "為 %1，不可超過 %2",
    "is %1, below the physical minimum of %2": "為 %1，低於物理下限 %2",
    "is %1, below %2: motion that slow would take days to plan and to emboss": "為 %1，低於 %2：這麼慢的運動要花好幾天規劃與列印",
    "needs %1, more than the controller can time (%2, 8 timer ticks per step)": "需要 %1，超過控制器能計時的上限（%2，每步 8 個計時器刻度）",
    "is %1, must exceed the dot pitch (%2) so neighbouring cells stay apart": "為 %1，必須大於點距（%2），相鄰的點字方才不會相連",
    "is %1, must exceed the cell height (%2)": "為 %1，必須大於點字方的高度（%2）",
    "%n cell(s) need %1 but the paper leaves %2 between the margins": "%n 方需要 %1，但紙張在邊界之間只有 %2",
    "%n line(s) need %1 but the paper leaves %2 between the margins": "%n 行需要 %1，但紙張在邊界之間只有 %2",
    "is %1, which puts back-side dots off the paper": "為 %1，背面的點會落在紙張之外",
    "is %1, wider than the paper (%2): one hammer could never reach it": "為 %1，比紙張（%2）還寬：有一支擊錘永遠打不到",
    "is %1, finer than half a carriage step (%2): unreachable at any speed": "為 %1，小於字車半步（%2）：任何速度都達不到",
    "is %1": "為 %1",
    "%1:": "%1：",
    "Cannot list the CUPS queues on %1: %2": "無法列出 CUPS 伺服器 %1 上的佇列：%2",
    "Cannot write %1: %2": "無法寫入 %1：%2",
    "Saving %1 failed: %2": "儲存 %1 失敗：%2",
    # A text file saved in its own encoding.
    "Cannot save %1: %2": "無法儲存 %1：%2",
    "%1 cannot be saved in its encoding, %2. Save it as UTF-8?": "%1 無法以原本的編碼 %2 儲存。要改存成 UTF-8 嗎？",
    "At line:column %1, %2. Nothing has been saved. UTF-8 holds every character, but programs that expect %3 may show it wrongly. Cancel leaves the file as it is; remove the character to keep %3.":
        "位於 行:欄 %1，%2。尚未儲存任何內容。UTF-8 能容納所有字元，但預期 %3 的程式可能顯示錯誤。按「取消」保留檔案原狀；刪除該字元即可維持 %3。",
    "A character does not fit the file's encoding": "有字元不符合檔案的編碼",
    "Save as &UTF-8": "存成 UTF-8(&U)",
    "Save the whole file as UTF-8 from now on": "此後整個檔案都存成 UTF-8",
    "Save nothing": "不儲存任何內容",
    "Not saved: %1 has a character that %2 cannot hold": "未儲存：%1 含有 %2 無法容納的字元",
    "The document cannot be laid out for this printer's page: %1": "無法依這台點字印表機的頁面排版此文件：%1",
    "front": "正面", "back": "背面", "front and back": "正面與背面",
    "back, as read after turning the sheet": "背面（翻頁後閱讀的方向）",
    "Sheet %1 (%2) - pages %3 / %4": "第 %1 張（%2）－ 第 %3 / %4 頁",
    "Tactus interpoint proof": "Tactus 雙面點字校稿",
    "Cannot write %1": "無法寫入 %1", "Cannot finish %1": "無法完成 %1",
    "Divider between print and braille": "明眼字與點字的分隔線",
    "%1 s": "%1 秒", "%1 min %2 s": "%1 分 %2 秒", "%1 h %2 min": "%1 小時 %2 分",
    "Braille editor and embosser print manager: edit print and braille side by side, preview interpoint sheets, emboss.":
        "點字編輯器與點字印表機管理：並排編輯明眼字與點字、預覽雙面點字、送印。",
    "Document to open (Markdown, text, DOCX, BRF, PEF).": "要開啟的文件（Markdown、純文字、DOCX、BRF、PEF）。",
    "liblouis table, e.g. en-ueb-g2.ctb or zh-tw.ctb.": "liblouis 點字表，例如 en-ueb-g2.ctb 或 zh-tw.ctb。",
    "Preview side: front, back or both.": "預覽面：front、back 或 both。",
    "Sheet to preview.": "要預覽的紙張。",
    "User interface language, e.g. zh_TW.": "介面語言，例如 zh_TW。",
    "Save a picture of the window and quit.": "儲存視窗畫面後結束。",
    "Panel to show: preview, motion, vibration, profile, printer.": "要顯示的面板：preview、motion、vibration、profile、printer。",
    "Do not offer to recover autosaved work.": "不要詢問是否復原自動儲存的內容。",
    "Braille": "點字",
    "The braille of each paragraph. Type with S D F J K L as dots 3 2 1 4 5 6; space, backspace and delete edit cells":
        "每一段的點字。以 S D F J K L 輸入第 3 2 1 4 5 6 點；空白鍵、退格鍵與刪除鍵編輯點字方",
    "Find and Replace": "尋找與取代", "Find": "尋找", "Replace with": "取代為",
    "&Match case": "大小寫須相符(&M)", "&Whole words": "全字拼寫須相符(&W)", "Search result": "搜尋結果",
    "F&ind:": "尋找(&I)：", "Re&place with:": "取代為(&P)：", "Find &Next": "找下一個(&N)",
    "Find Pre&vious": "找上一個(&V)", "&Replace": "取代(&R)", "Replace &All": "全部取代(&A)",
    "\u201c%1\u201d not found": "找不到「%1」", "Found on line %1": "在第 %1 行找到", "%n replaced": "已取代 %n 處",
    "Tactus": "Tactus", "Preview": "預覽", "Motion": "運動", "Vibration": "振動", "Printer profile": "印表機設定檔",
    "Braille toolbar": "點字工具列", "&Table:": "點字表(&T)：", "Position": "位置", "Status": "狀態",
    "&New": "新增(&N)", "&Open or Import...": "開啟或匯入(&O)...", "&Save": "儲存(&S)", "Save &As...": "另存新檔(&A)...",
    "Export &BRF...": "匯出 BRF(&B)...", "Export &PEF...": "匯出 PEF(&P)...", "&Quit": "結束(&Q)",
    "&Undo": "復原(&U)", "&Redo": "重做(&R)", "&Find and Replace...": "尋找與取代(&F)...",
    "Go to &print text": "移到明眼字(&P)", "Go to &braille": "移到點字(&B)", "Go to pre&view": "移到預覽(&V)",
    "Choose braille &table": "選擇點字表(&T)", "Go to &motion": "移到運動(&M)", "Go to vi&bration": "移到振動(&B)",
    "Go to printer pro&file": "移到印表機設定檔(&F)", "&Keyboard Shortcuts": "鍵盤快速鍵(&K)", "&About Tactus": "關於 Tactus(&A)",
    "&File": "檔案(&F)", "Open &Recent": "最近開啟(&R)", "&Edit": "編輯(&E)", "&View": "檢視(&V)", "&Help": "說明(&H)",
    # The structured print pane: styles as a word processor names them.
    "St&yles": "樣式(&Y)", "&Body text": "內文(&B)", "Heading &%1": "標題 %1(&%1)", "B&ulleted list": "項目符號清單(&U)",
    "&Numbered list": "編號清單(&N)", "&Quotation": "引文(&Q)", "&Page break": "分頁(&P)", "Bol&d": "粗體(&D)",
    "&Italic": "斜體(&I)", "Und&erline": "底線(&E)", "Bo&x": "方框(&X)", "Show &codes": "顯示代碼(&C)",
    "Show the print text's Markdown codes instead of its styles": "以 Markdown 代碼顯示明眼字，而不是其樣式",
    "The print text with its styles: headings, lists, tables, emphasis; Styles menu to change them":
        "帶樣式的明眼字：標題、清單、表格、強調；用「樣式」功能表變更",
    "Braille page break": "點字分頁",
    "Heading level %1": "標題層級 %1", "List item %1": "清單項目 %1", "List item": "清單項目",
    "Quotation": "引文", "Note": "註解", "Table header row, %1 columns": "表格標題列，%1 欄",
    # A box's lines (boxed material) in the structured print pane.
    "Box": "方框", "End of box": "方框結束",
    "Table row %1 of %2": "表格第 %1 列，共 %2 列",
    "Translating with %1": "正在以 %1 轉譯", "Cannot use table %1: %2": "無法使用點字表 %1：%2", "Braille table: %1": "點字表：%1",
    "Open or import": "開啟或匯入",
    "Documents (*.md *.markdown *.txt *.docx *.odt *.brf *.pef);;All files (*)": "文件 (*.md *.markdown *.txt *.docx *.odt *.brf *.pef);;所有檔案 (*)",
    # Save As's formats (widgets/save_formats.cpp).
    "Word document (*.docx)": "Word 文件 (*.docx)",
    "OpenDocument text (*.odt)": "OpenDocument 文字文件 (*.odt)",
    "PEF braille (*.pef)": "PEF 點字 (*.pef)",
    "Documents (*.md *.markdown *.txt *.docx *.brf *.pef);;All files (*)": "文件 (*.md *.markdown *.txt *.docx *.brf *.pef);;所有檔案 (*)",
    # Tactile graphics (觸覺圖形) opened in the app: what the graphic is, said and shown.
    "Documents (*.md *.markdown *.txt *.docx *.odt *.brf *.pef *.svg *.png *.jpg *.jpeg);;Tactile graphics (*.svg *.png *.jpg *.jpeg);;All files (*)":
        "文件 (*.md *.markdown *.txt *.docx *.odt *.brf *.pef *.svg *.png *.jpg *.jpeg);;觸覺圖形 (*.svg *.png *.jpg *.jpeg);;所有檔案 (*)",
    "Documents (*.md *.markdown *.txt *.docx *.brf *.pef *.svg *.png *.jpg *.jpeg);;Tactile graphics (*.svg *.png *.jpg *.jpeg);;All files (*)":
        "文件 (*.md *.markdown *.txt *.docx *.brf *.pef *.svg *.png *.jpg *.jpeg);;觸覺圖形 (*.svg *.png *.jpg *.jpeg);;所有檔案 (*)",
    "Graphic: %1.": "圖形：%1。",
    "Labels: %1.": "標籤：%1。",
    "%n dot(s).": "%n 點。",
    "Graphic: %n dot(s).": "圖形：%n 點。",
    "Graphic %1 | %n sheet(s)": "圖形 %1 | %n 張",
    "Sheet %1 %2: %3": "第 %1 張%2：%3",
    "%1. %2": "%1。%2",
    "Warning: %1": "警告：%1",
    "Cannot lay out %1 again: %2": "無法重新排版 %1：%2",
    "cancelled": "已取消",
    "Cannot send %1 to a CUPS queue: a tactile graphic is embossed on a device (choose it in the printer panel)":
        "無法將 %1 送到 CUPS 佇列：觸覺圖形須在點字印表機上列印（請在印表機面板選擇裝置）",
    "Tactile graphics": "觸覺圖形",
    # A drawing open on its own: the print pane holds what it is, not a document to save.
    "Cannot save %1: a tactile graphic is kept in its own file; emboss or plan it, or open a document to save":
        "無法儲存 %1：觸覺圖形保存在它自己的檔案中；請列印或規劃它，或開啟文件再儲存",
    "What the tactile graphic is: its title, description, labels and dots": "這個觸覺圖形的內容：標題、描述、標籤與點數",
    "Dot spacing along a solid line": "實線的點距",
    "Dot spacing along a dotted line": "點線的點距",
    "Gap between dashes": "虛線段之間的間隔",
    "Texture row spacing": "紋理的行距",
    "Dot spacing along a texture row": "紋理行上的點距",
    "Opening %1": "正在開啟 %1", "Cancel": "取消", "%1 percent": "百分之 %1",
    "Cancelled; the document is unchanged": "已取消，文件未變更", "Cannot open %1: %2": "無法開啟 %1：%2",
    "the document": "文件", "Opened %1: %n sheet(s)": "已開啟 %1：%n 張",
    "%n line(s) could not be translated; they are left out of the braille": "有 %n 行無法轉譯，未列入點字",
    "Sheet %1 of %2%3 | line %4 | cell %5 | print page %6": "第 %1 張，共 %2 張%3 | 第 %4 行 | 第 %5 方 | 原書第 %6 頁",
    "Print page break": "原書換頁", "Print page break, page %1": "原書換頁，第 %1 頁",
    ", back": "，背面", ", front": "，正面", "Untitled": "未命名", "Save as Markdown": "另存為 Markdown", "Save as": "另存新檔", "Plain text (*.txt)": "純文字 (*.txt)",
    "Markdown (*.md)": "Markdown (*.md)", "Saved %1": "已儲存 %1", "untitled": "未命名", "PEF (*.pef)": "PEF (*.pef)",
    "Braille ASCII (*.brf)": "點字 ASCII (*.brf)", "Export": "匯出", "Cannot export %1: %2": "無法匯出 %1：%2",
    "Exported %1 (%n sheet(s))": "已匯出 %1（%n 張）", "Print preview to PDF": "將預覽列印為 PDF", "PDF (*.pdf)": "PDF (*.pdf)",
    "Wrote proof %1": "已寫出校稿 %1", "Save the changes to %1?": "要儲存對 %1 的變更嗎？",
    "Cannot plan the job: %1": "無法規劃列印工作：%1", "Cannot read the autosaved copy %1: %2": "無法讀取自動儲存的副本 %1：%2",
    "Recovered": "已復原", "Recovered unsaved changes to %1": "已復原 %1 未儲存的變更", "an untitled document": "未命名文件",
    "Recover unsaved work": "復原未儲存的內容",
    "Tactus closed without saving %1 (autosaved %2). Recover it?": "Tactus 關閉時 %1 尚未儲存（自動儲存於 %2）。要復原嗎？",
    "Keyboard Shortcuts": "鍵盤快速鍵", "Shortcuts": "快速鍵", "Action": "動作", "Shortcut": "快速鍵",
    "Braille pane: dots 1 2 3 4 5 6 (chord, released together)": "點字窗格：第 1 2 3 4 5 6 點（同時按下、一起放開）",
    "F D S J K L": "F D S J K L", "Braille pane: blank cell / erase cell": "點字窗格：空方 / 刪除點字方",
    "Space / Backspace, Delete": "空白鍵 / 退格鍵、刪除鍵", "Preview: move between cells / lines": "預覽：在點字方 / 行之間移動",
    "Arrow keys": "方向鍵", "Preview: turn to the other side": "預覽：翻到另一面", "Space": "空白鍵",
    "Preview: previous / next sheet": "預覽：上一張 / 下一張", "PgUp / PgDown": "PgUp / PgDown",
    "Move between panes": "在窗格之間移動", "Tab / Shift+Tab": "Tab / Shift+Tab", "About Tactus": "關於 Tactus",
    "<p><b>Tactus %1</b></p><p>Braille editor and embosser print manager.</p><p>Licensed under the GNU GPL, version 3 or later.</p>":
        "<p><b>Tactus %1</b></p><p>點字編輯器與點字印表機管理程式。</p><p>依 GNU GPL 第 3 版或更新版本授權。</p>",
    "Sheet": "紙張", "Pass": "行程", "Quantity": "物理量", "Position (mm)": "位置 (mm)", "Velocity (mm/s)": "速度 (mm/s)",
    "Acceleration (mm/s\u00b2)": "加速度 (mm/s\u00b2)", "Jerk (mm/s\u00b3)": "加加速度 (mm/s\u00b3)",
    "Compare &profile shapes": "比較運動曲線(&P)", "S&heet:": "紙張(&H)：", "P&ass:": "行程(&A)：", "&Show:": "顯示(&S)：",
    "Carriage motion chart": "字車運動圖", "Time estimates": "時間估計", "Profile shapes on this pass": "此行程的各種運動曲線",
    "Profile shape": "運動曲線", "Pass time": "行程時間", "Versus lower bound": "相對於下限", "Strikes of this pass": "此行程的擊點",
    "Time (ms)": "時間 (ms)", "Carriage (mm)": "字車 (mm)", "Side": "面", "Residual (\u00b5m)": "殘留振動 (\u00b5m)",
    "No plan yet": "尚未規劃",
    "Sheet %1: %2 (lower bound %3, %4). Document, %5 sheets: %6 (lower bound %7, %8).":
        "第 %1 張：%2（下限 %3，%4）。整份文件 %5 張：%6（下限 %7，%8）。",
    "This sheet is blank.": "這張是空白的。", "Pass %1 (%2, %3 strikes): %4, lower bound %5.": "行程 %1（%2，%3 個擊點）：%4，下限 %5。",
    "Planned (auto-tuned)": "規劃（自動調校）", "Strikes": "擊點", "Trapezoid": "梯形", "S-curve (smoothstep)": "S 曲線（smoothstep）",
    "Jerk-limited (7 segments)": "限制加加速度（7 段）", "Sheet %1, pass %2": "第 %1 張，行程 %2",
    "%1 against time for sheet %2, pass %3: %4 strikes over %5; from %6 to %7. The strike table lists the same data.":
        "第 %2 張行程 %3 的%1對時間：%4 個擊點，歷時 %5；範圍 %6 到 %7。擊點表列出相同資料。",
    "Preview scroll area": "預覽捲動區", "&Front": "正面(&F)", "&Back": "背面(&B)", "Front &and back": "正面與背面(&A)",
    "&Previous sheet": "上一張(&P)", "&Next sheet": "下一張(&N)", "Zoom &in": "放大(&I)", "Zoom &out": "縮小(&O)",
    "&High contrast": "高對比(&H)", "Print preview to P&DF...": "將預覽列印為 PDF(&D)...", "Preview controls": "預覽控制", "Preview view controls": "預覽顯示控制", "View": "檢視",
    "Preview status": "預覽狀態", "Print text": "明眼字",
    "One paragraph per line: # for headings, - for list items, *italic*, **bold**": "每行一段：# 為標題、- 為清單項目、*斜體*、**粗體**",
    "Paper": "紙張", "Width": "寬度", "mm": "mm", "Height": "高度", "Left margin": "左邊界", "Top margin": "上邊界",
    "Braille geometry": "點字幾何", "Dot pitch": "點距", "Cell pitch": "方距", "Line pitch": "行距",
    "Back offset across": "背面水平偏移", "Back offset down": "背面垂直偏移", "Head and carriage": "打點頭與字車",
    "Concave hammer offset": "凹錘偏移", "Hammer dwell": "擊錘停留", "s": "秒", "Carriage steps": "字車步數", "steps/mm": "步/mm",
    "Carriage top speed": "字車最高速度", "mm/s": "mm/s", "Carriage acceleration": "字車加速度", "mm/s\u00b2": "mm/s\u00b2",
    "Carriage jerk": "字車加加速度", "mm/s\u00b3": "mm/s\u00b3", "Carriage backlash": "字車背隙", "Dynamics and vibration": "動態與振動",
    "Head mass": "打點頭質量", "kg": "kg", "Belt stiffness": "皮帶剛性", "N/m": "N/m", "Damping ratio": "阻尼比",
    "Position tolerance at the strike": "擊點時的位置容許誤差", "\u00b5m": "\u00b5m", "Profile fields": "設定檔欄位",
    "Profile check": "設定檔檢查", "&Load profile...": "載入設定檔(&L)...", "Sa&ve profile...": "儲存設定檔(&V)...",
    "&Defaults": "預設值(&D)", "Load printer profile": "載入印表機設定檔", "Profiles (*.json)": "設定檔 (*.json)",
    "Save printer profile": "儲存印表機設定檔", "%1 to %2 %3": "%1 到 %2 %3", "%1 in %2": "%1（%2）",
    "Range %1; profile field %2": "範圍 %1；設定檔欄位 %2",
    "%1 %2. The plan and preview keep the last valid profile.": "%1 %2。規劃與預覽仍使用上一個有效的設定檔。",
    "Profile is valid.": "設定檔有效。", "Cannot load %1: %2": "無法載入 %1：%2", "Loaded profile %1": "已載入設定檔 %1",
    "Cannot save %1: %2": "無法儲存 %1：%2", "Saved profile to %1": "已將設定檔儲存到 %1",
    "Interpoint preview": "雙面點字預覽",
    "Arrow keys move between cells; Page Up and Page Down change sheet": "方向鍵在點字方之間移動；Page Up 與 Page Down 換頁",
    "Sheet %1 %2, line %3, cell %4": "第 %1 張%2，第 %3 行，第 %4 方", ": no page": "：沒有這一頁", ": blank": "：空方",
    "dots %1": "第 %1 點", ", in the word \u201c%1\u201d": "，在「%1」中", "No document": "沒有文件", "Sheet %1 of %2": "第 %1 張，共 %2 張",
    "; %n front and back dots too close": "；有 %n 組正背面點距離過近", "Braille table": "點字表",
    "The language and braille code the print is translated with": "用來轉譯明眼字的語言與點字系統",
    "Step response against the targets": "步階響應與目標比較", "Value": "數值", "Target": "目標", "Result": "結果",
    "Natural frequencies": "自然頻率", "Residual vibration at the strikes": "擊點時的殘留振動",
    "Residual vibration histogram": "殘留振動直方圖", "Frequency response chart": "頻率響應圖", "pass": "通過", "FAIL": "未通過",
    "Overshoot": "超越量", "%1 %": "%1 %", "< %1 %": "< %1 %", "Rise time (10-90 %)": "上升時間（10-90 %）", "%1 ms": "%1 ms",
    "< %1 ms": "< %1 ms", "Settling time (2 %)": "安定時間（2 %）", "never settles": "無法安定",
    "%1 model; natural frequencies %2 Hz; \u221a(k/m) = %3 rad/s; damping ratio %4.": "%1模型；自然頻率 %2 Hz；\u221a(k/m) = %3 rad/s；阻尼比 %4。",
    "Two-inertia": "雙慣量", "One-inertia": "單慣量", "Magnitude (dB)": "增益 (dB)", "Phase (degrees)": "相位（度）",
    "Frequency (Hz)": "頻率 (Hz)", "dB": "dB", "degrees": "度", "Head position versus command": "打點頭位置對命令",
    "Peak %1 dB at %2 Hz; %3 points from %4 to %5 Hz.": "峰值 %1 dB 於 %2 Hz；%3 個點，從 %4 到 %5 Hz。",
    "All targets met": "全部達到目標", "Some targets are not met": "部分未達目標", "sheet %1, pass %2": "第 %1 張行程 %2",
    "Nominal machine": "標稱機器", "Worst case over the band": "參數範圍內最差情況", "Residual up to (\u00b5m)": "殘留振動上限 (\u00b5m)",
    "Residual vibration per strike": "每個擊點的殘留振動", "Strikes": "擊點",
    "%1 strikes on %2 planned sheets: worst case %3 \u00b5m at %4 (tolerance %5 \u00b5m) \u2014 %6.":
        "已規劃 %2 張共 %1 個擊點：最差 %3 \u00b5m，位於%4（容許 %5 \u00b5m）\u2014 %6。",
    "within tolerance": "在容許範圍內", "OVER TOLERANCE": "超出容許範圍",
    # Printer panel, six-key entry, table names.
    "waiting": "等待中", "embossing": "列印中", "paused": "已暫停", "done": "已完成", "stopped": "已停止",
    "cancelled": "已取消",
    "Emboss the file on the last used embosser once it is open.": "檔案開啟後，以上次使用的點字印表機列印。",
    "dots %1": "點 %1", "Printer": "印表機", "Go to p&rinter": "前往印表機(&R)", "&Emboss": "列印點字(&E)",
    "Open the menu bar": "開啟選單列",
    "Warning: the table %1 does not suit all of this text (%2). Ctrl+T chooses another table.":
        "警告：點字表 %1 不適用於這份文字的全部內容（%2）。按 Ctrl+T 選擇其他點字表。",
    "Embosser": "點字印表機",
    "Serial ports with their USB descriptions, HID bridges, parallel ports, and the built-in simulator":
        "序列埠（含 USB 說明）、HID 轉接器、平行埠，以及內建模擬器",
    "&Refresh": "重新整理(&R)", "&Connect": "連線(&C)", "Not connected": "未連線", "Controller status": "控制器狀態",
    "Fault": "故障", "Job queue": "工作佇列", "Document": "文件", "State": "狀態", "Progress": "進度", "Sheet": "紙張",
    "&Pause": "暫停(&P)", "Res&ume": "繼續(&U)", "Ca&ncel job": "取消工作(&N)",
    "Braille page to resume from": "從哪一個點字頁繼續", "Resume from pa&ge": "從指定頁繼續(&G)", "Link log": "連線紀錄",
    "E&mbosser:": "點字印表機(&M)：", "Lin&k log (for technicians):": "連線紀錄（技術人員用）(&K)：",
    "Listing devices: %1": "列出裝置：%1", "Connecting to %1": "正在連線到 %1",
    "Cannot connect to %1: %2. Check that it is switched on and plugged in, then try again.":
        "無法連線到 %1：%2。請確認電源已開啟且纜線已接好，然後再試一次。",
    "Dis&connect": "中斷連線(&C)", "Connected to %1": "已連線到 %1", "Disconnected from %1": "已與 %1 中斷連線",
    "No answer from the embosser": "點字印表機沒有回應",
    "The embosser does not answer (%1). Check the cable and the power switch.":
        "點字印表機沒有回應（%1）。請檢查纜線與電源開關。",
    "Connected to %1: %2": "已連線到 %1：%2", "Progress of %1": "%1 的進度",
    "Queued %1 (job %2) from sheet %3": "已將 %1 排入佇列（工作 %2），從第 %3 張開始",
    "%1 added to the queue": "%1 已加入佇列",
    "Embossing %1: sheet %2 of %3, %4 percent": "正在列印 %1：第 %2 張，共 %3 張，百分之 %4",
    "%1: sheet %2 of %3": "%1：第 %2 張，共 %3 張", "%1: %2 percent, sheet %3 of %4": "%1：百分之 %2，第 %3 張，共 %4 張",
    "Embossing %1 from sheet %2": "正在列印 %1，從第 %2 張開始", "Embossing %1": "正在列印 %1",
    "Cannot plan the job: %1": "無法規劃工作：%1",
    "Link: %1 frames sent, %2 resent, %3 bytes, %4 NAKs, %5 timeouts, %6 reconnects, %7 restarts":
        "連線：已傳送 %1 個訊框，重送 %2 個，%3 位元組，%4 次 NAK，%5 次逾時，%6 次重新連線，%7 次重新啟動",
    "all %1 strikes checked against the plan": "全部 %1 個擊點均已與規劃核對",
    "the strikes could not be checked: %1": "無法核對擊點：%1",
    "%1 strikes embossed but %2 planned: the simulator disagrees with the plan": "已列印 %1 個擊點，但規劃為 %2 個：模擬器與規劃不符",
    "Embossed %1": "已列印 %1", "%1 cancelled; resume from sheet %2": "%1 已取消；可從第 %2 張繼續",
    "%1 stopped at sheet %2: %3. The queue is kept; fix the problem, then resume from sheet %2.":
        "%1 停在第 %2 張：%3。佇列已保留；排除問題後，請從第 %2 張繼續。",
    "Pause requested: the embosser stops at the end of the current move": "已要求暫停：點字印表機會在目前動作結束時停止",
    "Pausing": "正在暫停", "Resume requested": "已要求繼續", "Resuming": "正在繼續", "Cancel requested": "已要求取消",
    "Page %1 is not in %2 (it has %3 pages)": "%2 沒有第 %1 頁（共 %3 頁）",
    "Step timing tolerance": "步進時間容許誤差", "of a step interval": "個步進間隔",
    "Unified English Braille": "統一英文點字", "English Braille American Edition": "美國版英文點字",
    "Taiwanese braille (bopomofo)": "台灣國語點字（注音）", "current Chinese braille": "現行中文點字",
    "two-cell Chinese braille": "雙拼中文點字", "uncontracted": "未縮寫", "partly contracted": "部分縮寫",
    "contracted": "縮寫", "grade %1": "第 %1 級", ", ": "，",
    # The printer panel as a spool client.
    "all %1 strikes of sheets %2 to %3 checked against the plan": "第 %2 至 %3 張的全部 %1 個擊點均已與規劃核對",
    "%1 is being embossed. Quit anyway?": "%1 正在列印。仍要結束嗎？",
    "The job stays in the print queue. The sheet in the embosser now is discarded; the rest is embossed when Tactus or tactus-cli serve runs printer %1 again.":
        "工作會留在列印佇列中。點字印表機中目前這張紙會作廢；其餘部分會在 Tactus 或 tactus-cli serve 再次執行印表機 %1 時列印。",
    "&Keep embossing": "繼續列印(&K)",
    "The printer's page is too small for the pages of %1. Lay the braille out again on the printer's page?": "印表機的頁面放不下 %1 的頁面。要在印表機的頁面上重新排版點字嗎？",
    # The page-too-small question: the file's declared page, volume by volume.
    "The pages of %1 are %2 cells by %3 lines; the printer's page holds %4 cells by %5 lines.":
        "%1 的頁面為每行 %2 方、每頁 %3 行；印表機的頁面只容納每行 %4 方、每頁 %5 行。",
    "volume %1, %2 cells by %3 lines": "第 %1 冊，每行 %2 方、每頁 %3 行",
    "volume %1, %2 cells by %3 lines, too large": "第 %1 冊，每行 %2 方、每頁 %3 行，太大",
    "The pages of %1 differ by volume: %2. The printer's page holds %3 cells by %4 lines.":
        "%1 各冊的頁面大小不同：%2。印表機的頁面只容納每行 %3 方、每頁 %4 行。",
    "; ": "；",
    # A PEF's structure sent to a CUPS queue could not be written.
    "Cannot send %1: %2": "無法送出 %1：%2",
    "Nothing has been embossed or exported. Reflow lays the braille out again on the printer's page, so its lines and pages change. Stop leaves it as it is; choose a printer whose page is large enough.":
        "尚未列印或匯出任何內容。「重新排版」會在印表機的頁面上重新排版點字，行與頁都會改變。「停止」則保持原樣；請選擇頁面夠大的印表機。",
    "The printer's page is too small": "印表機的頁面太小",
    "&Reflow": "重新排版(&R)",
    "&Stop": "停止(&S)",
    "Lay the braille out again on the printer's page and go on": "在印表機的頁面上重新排版點字並繼續",
    "Emboss or export nothing": "不列印也不匯出",
    "Stopped: nothing was embossed or exported (the printer's page is too small for %1)": "已停止：未列印或匯出任何內容（印表機的頁面放不下 %1）",
    "The document cannot be laid out for this printer's page: %1": "無法依此印表機的頁面排版文件：%1",
    "The braille's own pages, sections and volumes are kept again": "已恢復保留點字原有的頁面、段落與分冊",
    "The braille is laid out again on the printer's page: its own pages, sections and volumes are kept only while it holds nothing but braille rows that fit the page":
        "點字已在印表機的頁面上重新排版：只有在文件只含放得下頁面的點字行時，才會保留原有的頁面、段落與分冊",
    "The print spool's jobs, from this window, tactus-cli and the network": "列印佇列中的工作，來自本視窗、tactus-cli 與網路",
    "Job": "工作", "Simulator faults (built-in simulator)": "模擬器故障（內建模擬器）", "Paper out": "缺紙",
    "The feeder runs empty; the simulated operator loads paper 5 seconds later": "送紙器沒紙了；模擬的操作員會在 5 秒後補紙",
    "Pull the cable": "拔除纜線", "The cable is out for 5 seconds; the link reconnects": "纜線拔除 5 秒；連線會重新建立",
    "Line noise": "線路雜訊",
    "For 2 seconds, 1 byte in 100 is lost, changed or doubled; the link sends again":
        "持續 2 秒，每 100 個位元組中有 1 個遺失、改變或重複；連線會重新傳送",
    "Controller reset": "控制器重設",
    "A watchdog reset: the controller keeps its place and the job continues": "看門狗重設：控制器記得目前位置，工作繼續進行",
    "No place for the print queue: set TACTUS_SPOOL_DB or HOME.": "沒有地方存放列印佇列：請設定 TACTUS_SPOOL_DB 或 HOME。",
    "Cannot open the print queue: %1": "無法開啟列印佇列：%1",
    "“%1” is not a device Tactus can open: %2. Examples: sim, serial:/dev/ttyUSB0?baud=57600, pty:/dev/pts/3, hid:10c4:ea80, lpt:/dev/parport0.":
        "「%1」不是 Tactus 能開啟的裝置：%2。範例：sim、serial:/dev/ttyUSB0?baud=57600、pty:/dev/pts/3、hid:10c4:ea80、lpt:/dev/parport0。",
    "Cannot set up a printer for %1: %2": "無法為 %1 設定印表機：%2",
    "Set up printer %1 on %2 with the profile being edited": "已在 %2 上設定印表機 %1，使用正在編輯的設定檔",
    "Cannot give printer %1 the profile being edited: %2": "無法將正在編輯的設定檔套用到印表機 %1：%2",
    "Printer %1 now uses the profile being edited": "印表機 %1 現在使用正在編輯的設定檔",
    "Printer %1 is run by %2: this window shows its jobs": "印表機 %1 由 %2 執行：本視窗顯示它的工作",
    "Printer %1: %2; this window shows its jobs": "印表機 %1：%2；本視窗顯示它的工作",
    "This window runs printer %1": "本視窗執行印表機 %1", "This window no longer runs printer %1": "本視窗不再執行印表機 %1",
    "job %1: ": "工作 %1：", "run by this window": "由本視窗執行", "run by %1": "由 %1 執行",
    "no runner: start tactus-cli serve or press Connect": "沒有執行者：請啟動 tactus-cli serve 或按「連線」",
    "%1 %2": "%1 %2", "Printer %1, %2": "印表機 %1，%2", "Job %1: %2 sent to the queue": "工作 %1：%2 已送入佇列",
    "%1: %2": "%1：%2", "%1 is embossed again from sheet %2": "%1 從第 %2 張重新列印",
    "Simulator: the paper runs out": "模擬器：紙張用完", "Simulator: the cable is pulled for 5 seconds": "模擬器：纜線拔除 5 秒",
    "Simulator: line noise for 2 seconds": "模擬器：線路雜訊 2 秒", "Simulator: the controller resets": "模擬器：控制器重設",
    "The built-in simulator, serial ports with their USB descriptions, HID bridges and parallel ports, and the Tactus queues of the CUPS servers this computer sees, marked network queue; or type a device string such as pty:/dev/pts/3, serial:/dev/ttyUSB0?baud=57600 or ipp://server/printers/Embosser":
        "內建模擬器、序列埠（含 USB 說明）、HID 轉接器與平行埠，以及本電腦看得到的 CUPS 伺服器上的 Tactus 佇列（標為網路佇列）；也可以輸入裝置字串，例如 pty:/dev/pts/3、serial:/dev/ttyUSB0?baud=57600 或 ipp://server/printers/Embosser",
    "Embosser device": "點字印表機裝置", "Disconnected from printer %1": "已與印表機 %1 中斷連線",
    "Cannot queue %1: %2": "無法將 %1 排入佇列：%2", "Queued %1 as job %2 on printer %3": "已將 %1 排入印表機 %3，工作 %2",
    "The print queue cannot be written (%1): this window stopped running printer %2":
        "無法寫入列印佇列（%1）：本視窗已停止執行印表機 %2",
    "Cannot read the print queue: %1": "無法讀取列印佇列：%1", "Embossing %1 (job %2) on %3": "正在以 %3 列印 %1（工作 %2）",
    "%1 paused: %2": "%1 已暫停：%2", "%1 waits: %2": "%1 等待中：%2", "%1 cancelled": "%1 已取消",
    "%1 stopped: %2. The job is kept; fix the problem, then resume it.": "%1 已停止：%2。工作已保留；排除問題後請繼續。",
    "job %1": "工作 %1", "%1 The printer is running again.": "%1 印表機已恢復運作。",
    "%1 goes on: the printer is running again": "%1 繼續進行：印表機已恢復運作",
    # Printing to a CUPS queue: 網路佇列 network queue, 伺服器 server.
    "held": "保留中", "aborted": "已中止", "sending": "傳送中", "not sent": "未送出", "cancelling": "取消中",
    "The built-in simulated embosser, on this computer": "內建的模擬點字印表機，在本電腦上",
    "An embosser on a cable to this computer": "以纜線連接本電腦的點字印表機",
    "Network queue %1 on %2": "網路佇列 %1（位於 %2）",
    "Network queue %1 on the CUPS server %2": "網路佇列 %1，位於 CUPS 伺服器 %2",
    "A Tactus queue on another computer: the document is sent there over the network and laid out with that embosser's profile":
        "另一台電腦上的 Tactus 佇列：文件經網路送到那裡，並依該點字印表機的設定檔排版",
    "%n Tactus queue(s) found on CUPS servers": "在 CUPS 伺服器上找到 %n 個 Tactus 佇列",
    "%1 is a CUPS queue: there is nothing to connect to. Ctrl+P sends the document to it.":
        "%1 是 CUPS 佇列，不需要連線。按 Ctrl+P 即可將文件送過去。",
    "\u201c%1\u201d is not a CUPS queue: %2": "「%1」不是 CUPS 佇列：%2",
    "%1 at %2": "%2 的 %1",
    "Cannot send %1: cannot write a copy to send (%2)": "無法送出 %1：無法寫入要送出的副本（%2）",
    "Sending %1 to %2 (%3)": "正在將 %1 送到 %2（%3）", "Sending %1 to %2": "正在將 %1 送到 %2",
    "Sent %1 to %2 as job %3": "已將 %1 送到 %2，工作 %3",
    "Embossing %1 on %2": "正在以 %2 列印 %1", "%1 waits on %2: %3": "%1 在 %2 等待中：%3",
    "%1: %n sheet(s) embossed": "%1：已列印 %n 張", "Job %1 on %2: %3": "%2 的工作 %1：%3",
    "%1: the job on %2 can no longer be followed: %3": "%1：無法再追蹤 %2 上的工作：%3",
    "%1 was not sent to %2: %3": "%1 未送到 %2：%3", "Embossed %1 on %2": "已以 %2 列印 %1",
    "%1 cancelled on %2": "%1 已在 %2 取消", "%1 cancelled on %2: %3": "%1 已在 %2 取消：%3",
    "%1 stopped on %2: %3": "%1 已在 %2 停止：%3",
    "Progress of the sheet in hand of %1": "%1 目前這張的進度",
    "%1: cancel sent to %2": "%1：已向 %2 送出取消", "Cancelling %1 on %2": "正在取消 %2 上的 %1",
    "Embosser device string for Ctrl+P and --emboss, e.g. sim, serial:/dev/ttyUSB0, pty:/dev/pts/3 or a CUPS queue ipp://server/printers/Embosser.":
        "Ctrl+P 與 --emboss 使用的點字印表機裝置字串，例如 sim、serial:/dev/ttyUSB0、pty:/dev/pts/3 或 CUPS 佇列 ipp://server/printers/Embosser。",
    "The plan's own speed": "依列印計畫的實際速度", "10 times faster": "快 10 倍",
    "As fast as the computer can": "以電腦能達到的最快速度", "Simulator speed": "模擬器速度", "Speed:": "速度：",
    "How fast the built-in simulator embosses: at the plan's own speed, as the embosser would, or faster. It sets the speed option of the device string, for example sim?speed=10":
        "內建模擬器的列印速度：依列印計畫的實際速度（與點字印表機相同），或更快。它會設定裝置字串的 speed 選項，例如 sim?speed=10",
    "The built-in simulator will run as %1 (%2); it takes effect at the next Connect or job":
        "內建模擬器將以 %1 執行（%2）；於下次連線或下一個工作時生效",
    "%1 times faster": "快 %1 倍", "Built-in simulated embosser": "內建模擬點字印表機",
    "Undone: %1": "已復原：%1", "Redone: %1": "已重做：%1", "%1 \u2014 Tactus": "%1 \u2014 Tactus",
    "%1 paused": "%1 已暫停", "%1 resumed": "%1 已繼續",
    "Invalid: %1. %2": "無效：%1。%2",
    "the text is mostly in Latin letters; for English, Unified English Braille (%1) suits it":
        "文字大多是拉丁字母；英文適合用統一英文點字（%1）",
    "the text is mostly Traditional Chinese; Taiwanese bopomofo braille (%1) suits it":
        "文字大多是繁體中文；適合用台灣注音點字（%1）",
    "the text is mostly Simplified Chinese; Chinese double-phonic braille (%1) suits it":
        "文字大多是簡體中文；適合用中文雙拼點字（%1）", "%1 is valid again.": "%1 又有效了。",
    # A book: its volumes, and what the printer panel embosses of it.
    "Volume %1 of %2, blank page": "第 %1 冊，共 %2 冊，空白頁", "Volume %1 of %2, page %3": "第 %1 冊，共 %2 冊，第 %3 頁",
    "Volume %1 of %2": "第 %1 冊，共 %2 冊", "Volume %1 of %2 is the last": "第 %1 冊（共 %2 冊）是最後一冊",
    "Volume": "冊", "Go to volume (%1, %2)": "前往某一冊（%1、%2）",
    "Previou&s volume": "上一冊(&S)", "Next vo&lume": "下一冊(&L)",
    "%1; %2": "%1；%2",
    "Emboss": "列印範圍", "Em&boss:": "列印(&B)：", "Pages:": "頁：",
    "The whole document, one volume of a book, or a range of braille pages": "整份文件、書的其中一冊，或一段點字頁",
    "Braille pages to emboss": "要列印的點字頁",
    "As the pages are numbered: 3-10, 5- (to the end), 7; in a book t1 for the title page, p1-p2 for the contents":
        "依頁面上的頁碼：3-10、5-（到最後）、7；書中 t1 為書名頁，p1-p2 為目錄",
    "e.g. 3-10, 5-, p1-p2": "例如 3-10、5-、p1-p2", "To emboss": "要列印的內容",
    "Whole document": "整份文件", "Page range": "頁碼範圍", "No pages chosen: %1": "未選擇任何頁：%1",
    "Whole document: %n sheet(s)": "整份文件：%n 張", "Volume %1 of %2: %n sheet(s)": "第 %1 冊，共 %2 冊：%n 張",
    "Pages %1 to %2: %n sheet(s)": "第 %1 頁到第 %2 頁：%n 張",
    # The book laid out in the background: the status bar's bar and button, and what is said.
    "Laying out the book": "正在排版書籍", "Cancel book layout": "取消書籍排版",
    "Book layout cancelled; the preview shows the pages laid out before": "已取消書籍排版；預覽顯示先前排好的頁面",
    "Laying out the book: %1 percent": "正在排版書籍：百分之 %1",
    "%n volume(s)": "%n 冊", "%n sheet(s)": "%n 張", "Opened %1: %2": "已開啟 %1：%2", "Book: %1": "書籍：%1",
    "The book could not be laid out: %1": "無法排版書籍：%1", "Book layout cancelled": "已取消書籍排版",
    # Book Settings: the book layout's rules and the title page's lines.
    "Boo&k Settings...": "書籍設定(&K)...", "Book Settings": "書籍設定",
    "Book settings: about %n sheet(s) per volume": "書籍設定：每冊約 %n 張",
    "How a book is divided into volumes and what each volume starts with. A document is laid out as a book when it is an EPUB, HTML or DAISY book, or longer than one volume.":
        "書籍如何分冊，以及每冊開頭放些什麼。文件為 EPUB、HTML 或 DAISY 書籍，或長度超過一冊時，會以書籍版面編排。",
    "Sheets per volume": "每冊張數", "&Sheets per volume:": "每冊張數(&S)：",
    "About this many sheets in each volume, its title page and contents included": "每冊約這麼多張，含書名頁與目錄",
    "Volumes start at heading level": "分冊起點的標題層級", "&Volumes start at heading level:": "分冊起點的標題層級(&V)：",
    "1: only at chapters; 2: at chapters and sections": "1：只在章；2：在章與節",
    "&Title page in each volume": "每冊都有書名頁(&T)", "&Contents pages in each volume": "每冊都有目錄頁(&C)",
    "Heading levels in the contents": "目錄列出的標題層級", "&Heading levels in the contents:": "目錄列出的標題層級(&H)：",
    "1: chapters only": "1：只列章", "Runnin&g heads": "書眉(&G)",
    "Title page (this document only)": "書名頁（僅限此文件）",
    "Title": "書名", "T&itle:": "書名(&I)：", "Author": "作者", "&Author:": "作者(&A)：",
    "Publisher": "出版者", "&Publisher:": "出版者(&P)：", "Year": "年份", "&Year:": "年份(&Y)：",
    "Transcribed by": "點字轉譯", "Transcri&bed by:": "點字轉譯(&B)：",
    "From the document": "取自文件", "No such line": "不加此行",
    # Saving over a file whose pictures the editor does not hold.
    # Pictures the editor keeps: lost only where the file cannot hold them.
    "%1 cannot keep %n of the document's pictures. Save anyway?": "%1 無法保留文件中的 %n 張圖片。仍要儲存嗎？",
    "Nothing has been saved. In %1 each of these pictures would be its description only. Cancel saves nothing; a DOCX or ODT file keeps every picture.":
        "尚未儲存任何內容。在 %1 中，這些圖片都只會剩下描述文字。按「取消」不儲存任何內容；DOCX 或 ODT 檔會保留每張圖片。",
    "Saving would lose pictures": "儲存會失去圖片",
    "&Save Without Them": "不含圖片儲存(&S)",
    "Save with the pictures' descriptions only": "儲存時只保留圖片的描述",
    "Not saved: %1 cannot keep %n picture(s)": "未儲存：%1 無法保留 %n 張圖片",
    "Picture without a description": "沒有描述的圖片",
    "Picture: %1": "圖片：%1",
    "Picture": "圖片",
    "Gr&aphic...": "圖形(&A)...",
    "Emboss Pictures as &Graphics": "將圖片列印為觸覺圖形(&G)",
    "Pictures not embossed as graphics: %1": "圖片未列印為觸覺圖形：%1",
    "Pictures are embossed as graphics, each after its description": "圖片將列印為觸覺圖形，各接在其描述之後",
    "Pictures are embossed as their descriptions only": "圖片只列印其描述",
    "Insert graphic": "插入圖形",
    "Pictures (*.svg *.png *.jpg *.jpeg)": "圖片 (*.svg *.png *.jpg *.jpeg)",
    "Description of %1 (what a reader who cannot see it needs to know):": "%1 的描述（看不見圖片的讀者需要知道的內容）：",
    "Not inserted: %1 needs a description, which is what a braille reader reads of it": "未插入：%1 需要描述，點字讀者讀到的就是這段描述",
    "Cannot insert %1: %2": "無法插入 %1：%2",
    "Cannot insert %1: only a document (not a text file or a graphic) holds pictures": "無法插入 %1：只有文件（不是純文字檔或圖形）能含有圖片",
    "Graphic %1 inserted: %2": "已插入圖形 %1：%2",
    "with %n picture file(s) beside it": "並在旁邊存入 %n 個圖片檔",
    "No&te": "註解(&T)", "Note %1: type its text": "註解 %1：請輸入內容",
    "&Raised": "上標(&R)", "&Lowered": "下標(&L)",
}


def main(path):
    tree = ET.parse(path)
    done = missing = 0
    for message in tree.iter("message"):
        source = message.findtext("source")
        tr = message.find("translation")
        if tr is None:
            tr = ET.SubElement(message, "translation")
        text = T.get(source)
        if text is None and source and source.startswith("Ctrl") or source in ("Shift+F1",):
            text = source  # key names stay as they are
        if text is None:
            missing += 1
            continue
        for child in list(tr):
            tr.remove(child)
        if message.get("numerus") == "yes":
            tr.text = None
            ET.SubElement(tr, "numerusform").text = text
        else:
            tr.text = text
        tr.attrib.pop("type", None)
        done += 1
    tree.write(path, encoding="utf-8", xml_declaration=True)
    print(f"{done} translated, {missing} left in English")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "resources/i18n/tactus_zh_TW.ts")
