<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="zh_TW">
<context>
    <name>QObject</name>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="21" />
        <source>typing</source>
        <translation>輸入</translation>
    </message>
    <message>
        <location filename="../../widgets/atomic_write.cpp" line="21" />
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="80" />
        <source>front</source>
        <translation>正面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="81" />
        <source>back, as read after turning the sheet</source>
        <translation>背面（翻頁後閱讀的方向）</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="82" />
        <source>front and back</source>
        <translation>正面與背面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="84" />
        <source>Sheet %1 (%2) - pages %3 / %4</source>
        <translation>第 %1 張（%2）－ 第 %3 / %4 頁</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="456" />
        <source>Tactus interpoint proof</source>
        <translation>Tactus 雙面點字校稿</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="463" />
        <source>Cannot write %1</source>
        <translation>無法寫入 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="474" />
        <source>Cannot finish %1</source>
        <translation>無法完成 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/accessibility.cpp" line="46" />
        <source>Divider between print and braille</source>
        <translation>明眼字與點字的分隔線</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="56" />
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="58" />
        <source>%1 min %2 s</source>
        <translation>%1 分 %2 秒</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="59" />
        <source>%1 h %2 min</source>
        <translation>%1 小時 %2 分</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="58" />
        <location filename="../../widgets/printer_panel_queues.cpp" line="42" />
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="59" />
        <location filename="../../widgets/printer_panel_queues.cpp" line="44" />
        <source>embossing</source>
        <translation>列印中</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="60" />
        <source>paused</source>
        <translation>已暫停</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="61" />
        <location filename="../../widgets/printer_panel_queues.cpp" line="48" />
        <source>done</source>
        <translation>已完成</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="43" />
        <source>held</source>
        <translation>保留中</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="62" />
        <location filename="../../widgets/printer_panel_queues.cpp" line="45" />
        <source>stopped</source>
        <translation>已停止</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="63" />
        <location filename="../../widgets/printer_panel_queues.cpp" line="46" />
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="47" />
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="116" />
        <source>the strikes could not be checked: %1</source>
        <translation>無法核對擊點：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="118" />
        <source>%1 strikes embossed but %2 planned: the simulator disagrees with the plan</source>
        <translation>已列印 %1 個擊點，但規劃為 %2 個：模擬器與規劃不符</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="121" />
        <source>all %1 strikes of sheets %2 to %3 checked against the plan</source>
        <translation>第 %2 至 %3 張的全部 %1 個擊點均已與規劃核對</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="123" />
        <source>all %1 strikes checked against the plan</source>
        <translation>全部 %1 個擊點均已與規劃核對</translation>
    </message>
</context>
<context>
    <name>SaveFormats</name>
    <message>
        <location filename="../../widgets/save_formats.cpp" line="18" />
        <source>Markdown (*.md)</source>
        <translation>Markdown (*.md)</translation>
    </message>
    <message>
        <location filename="../../widgets/save_formats.cpp" line="19" />
        <source>Plain text (*.txt)</source>
        <translation>純文字 (*.txt)</translation>
    </message>
    <message>
        <location filename="../../widgets/save_formats.cpp" line="20" />
        <source>Word document (*.docx)</source>
        <translation>Word 文件 (*.docx)</translation>
    </message>
    <message>
        <location filename="../../widgets/save_formats.cpp" line="21" />
        <source>OpenDocument text (*.odt)</source>
        <translation>OpenDocument 文字文件 (*.odt)</translation>
    </message>
    <message>
        <location filename="../../widgets/save_formats.cpp" line="22" />
        <source>Braille ASCII (*.brf)</source>
        <translation>點字 ASCII (*.brf)</translation>
    </message>
    <message>
        <location filename="../../widgets/save_formats.cpp" line="23" />
        <source>PEF braille (*.pef)</source>
        <translation>PEF 點字 (*.pef)</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../../app/gui/main.cpp" line="50" />
        <source>Braille editor and embosser print manager: edit print and braille side by side, preview interpoint sheets, emboss.</source>
        <translation>點字編輯器與點字印表機管理：並排編輯明眼字與點字、預覽雙面點字、送印。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="56" />
        <source>Document to open (Markdown, text, DOCX, BRF, PEF).</source>
        <translation>要開啟的文件（Markdown、純文字、DOCX、BRF、PEF）。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="59" />
        <source>liblouis table, e.g. en-ueb-g2.ctb or zh-tw.ctb.</source>
        <translation>liblouis 點字表，例如 en-ueb-g2.ctb 或 zh-tw.ctb。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="62" />
        <source>Preview side: front, back or both.</source>
        <translation>預覽面：front、back 或 both。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="64" />
        <source>Sheet to preview.</source>
        <translation>要預覽的紙張。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="67" />
        <source>User interface language, e.g. zh_TW.</source>
        <translation>介面語言，例如 zh_TW。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="70" />
        <source>Save a picture of the window and quit.</source>
        <translation>儲存視窗畫面後結束。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="73" />
        <source>Panel to show: preview, motion, vibration, profile, printer.</source>
        <translation>要顯示的面板：preview、motion、vibration、profile、printer。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="76" />
        <source>Emboss the file on the last used embosser once it is open.</source>
        <translation>檔案開啟後，以上次使用的點字印表機列印。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="78" />
        <source>Do not offer to recover autosaved work.</source>
        <translation>不要詢問是否復原自動儲存的內容。</translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="80" />
        <source>Embosser device string for Ctrl+P and --emboss, e.g. sim, serial:/dev/ttyUSB0, pty:/dev/pts/3 or a CUPS queue ipp://server/printers/Embosser.</source>
        <translation>Ctrl+P 與 --emboss 使用的點字印表機裝置字串，例如 sim、serial:/dev/ttyUSB0、pty:/dev/pts/3 或 CUPS 佇列 ipp://server/printers/Embosser。</translation>
    </message>
</context>
<context>
    <name>tactus::gui::Autosave</name>
    <message>
        <location filename="../../widgets/autosave.cpp" line="98" />
        <source>an untitled document</source>
        <translation>未命名文件</translation>
    </message>
    <message>
        <location filename="../../widgets/autosave.cpp" line="100" />
        <source>Recover unsaved work</source>
        <translation>復原未儲存的內容</translation>
    </message>
    <message>
        <location filename="../../widgets/autosave.cpp" line="101" />
        <source>Tactus closed without saving %1 (autosaved %2). Recover it?</source>
        <translation>Tactus 關閉時 %1 尚未儲存（自動儲存於 %2）。要復原嗎？</translation>
    </message>
</context>
<context>
    <name>tactus::gui::BookProgress</name>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="31" />
        <source>Laying out the book</source>
        <translation>正在排版書籍</translation>
    </message>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="35" />
        <location filename="../../widgets/book_progress.cpp" line="36" />
        <source>Cancel book layout</source>
        <translation>取消書籍排版</translation>
    </message>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="44" />
        <source>Book layout cancelled; the preview shows the pages laid out before</source>
        <translation>已取消書籍排版；預覽顯示先前排好的頁面</translation>
    </message>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="75" />
        <source>Laying out the book: %1 percent</source>
        <translation>正在排版書籍：百分之 %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/book_progress.cpp" line="92" />
        <source>%n volume(s)</source>
        <translation><numerusform>%n 冊</numerusform></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/book_progress.cpp" line="93" />
        <source>%n sheet(s)</source>
        <translation><numerusform>%n 張</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="97" />
        <source>Opened %1: %2</source>
        <translation>已開啟 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="99" />
        <source>Book: %1</source>
        <translation>書籍：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="100" />
        <source>The book could not be laid out: %1</source>
        <translation>無法排版書籍：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/book_progress.cpp" line="101" />
        <source>Book layout cancelled</source>
        <translation>已取消書籍排版</translation>
    </message>
</context>
<context>
    <name>tactus::gui::BookSettingsDialog</name>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="37" />
        <source>From the document</source>
        <translation>取自文件</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="48" />
        <source>Book Settings</source>
        <translation>書籍設定</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="51" />
        <source>How a book is divided into volumes and what each volume starts with. A document is laid out as a book when it is an EPUB, HTML or DAISY book, or longer than one volume.</source>
        <translation>書籍如何分冊，以及每冊開頭放些什麼。文件為 EPUB、HTML 或 DAISY 書籍，或長度超過一冊時，會以書籍版面編排。</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="54" />
        <source>Sheets per volume</source>
        <translation>每冊張數</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="55" />
        <source>About this many sheets in each volume, its title page and contents included</source>
        <translation>每冊約這麼多張，含書名頁與目錄</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="57" />
        <source>Volumes start at heading level</source>
        <translation>分冊起點的標題層級</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="58" />
        <source>1: only at chapters; 2: at chapters and sections</source>
        <translation>1：只在章；2：在章與節</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="60" />
        <source>&amp;Title page in each volume</source>
        <translation>每冊都有書名頁(&amp;T)</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="62" />
        <source>&amp;Contents pages in each volume</source>
        <translation>每冊都有目錄頁(&amp;C)</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="64" />
        <source>Heading levels in the contents</source>
        <translation>目錄列出的標題層級</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="64" />
        <source>1: chapters only</source>
        <translation>1：只列章</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="66" />
        <source>Runnin&amp;g heads</source>
        <translation>書眉(&amp;G)</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="70" />
        <source>Title</source>
        <translation>書名</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="72" />
        <source>Author</source>
        <translation>作者</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="73" />
        <source>Publisher</source>
        <translation>出版者</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="74" />
        <source>Year</source>
        <translation>年份</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="76" />
        <source>Transcribed by</source>
        <translation>點字轉譯</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="77" />
        <source>No such line</source>
        <translation>不加此行</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="81" />
        <source>&amp;Sheets per volume:</source>
        <translation>每冊張數(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="82" />
        <source>&amp;Volumes start at heading level:</source>
        <translation>分冊起點的標題層級(&amp;V)：</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="85" />
        <source>&amp;Heading levels in the contents:</source>
        <translation>目錄列出的標題層級(&amp;H)：</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="88" />
        <source>Title page (this document only)</source>
        <translation>書名頁（僅限此文件）</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="90" />
        <source>T&amp;itle:</source>
        <translation>書名(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="91" />
        <source>&amp;Author:</source>
        <translation>作者(&amp;A)：</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="92" />
        <source>&amp;Publisher:</source>
        <translation>出版者(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="93" />
        <source>&amp;Year:</source>
        <translation>年份(&amp;Y)：</translation>
    </message>
    <message>
        <location filename="../../widgets/book_settings.cpp" line="94" />
        <source>Transcri&amp;bed by:</source>
        <translation>點字轉譯(&amp;B)：</translation>
    </message>
</context>
<context>
    <name>tactus::gui::BookView</name>
    <message>
        <location filename="../../widgets/book_view.cpp" line="205" />
        <source>Volume %1 of %2, blank page</source>
        <translation>第 %1 冊，共 %2 冊，空白頁</translation>
    </message>
    <message>
        <location filename="../../widgets/book_view.cpp" line="206" />
        <source>Volume %1 of %2, page %3</source>
        <translation>第 %1 冊，共 %2 冊，第 %3 頁</translation>
    </message>
</context>
<context>
    <name>tactus::gui::BraillePane</name>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="50" />
        <source>Braille</source>
        <translation>點字</translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="52" />
        <source>The braille of each paragraph. Type with S D F J K L as dots 3 2 1 4 5 6; space, backspace and delete edit cells</source>
        <translation>每一段的點字。以 S D F J K L 輸入第 3 2 1 4 5 6 點；空白鍵、退格鍵與刪除鍵編輯點字方</translation>
    </message>
</context>
<context>
    <name>tactus::gui::EditorWidget</name>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="863" />
        <source>dots %1</source>
        <translation>點 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="128" />
        <source>Print page break</source>
        <translation>原書換頁</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="109" />
        <source>Braille page break</source>
        <translation>點字分頁</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="128" />
        <source>Print page break, page %1</source>
        <translation>原書換頁，第 %1 頁</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="139" />
        <source>Picture without a description</source>
        <translation>沒有描述的圖片</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="139" />
        <source>Picture: %1</source>
        <translation>圖片：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="147" />
        <source>Heading level %1</source>
        <translation>標題層級 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="152" />
        <source>List item %1</source>
        <translation>清單項目 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="153" />
        <location filename="../../widgets/editor_widget.cpp" line="154" />
        <source>List item</source>
        <translation>清單項目</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="156" />
        <source>Quotation</source>
        <translation>引文</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="158" />
        <source>Note</source>
        <translation>註解</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="160" />
        <source>Box</source>
        <translation>方框</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="162" />
        <source>End of box</source>
        <translation>方框結束</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="179" />
        <source>Table header row, %1 columns</source>
        <translation>表格標題列，%1 欄</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="180" />
        <source>Table row %1 of %2</source>
        <translation>表格第 %1 列，共 %2 列</translation>
    </message>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="859" />
        <source>blank cell</source>
        <translation>空方</translation>
    </message>
</context>
<context>
    <name>tactus::gui::EmbossChoice</name>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="20" />
        <source>Emboss</source>
        <translation>列印範圍</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="21" />
        <source>The whole document, one volume of a book, or a range of braille pages</source>
        <translation>整份文件、書的其中一冊，或一段點字頁</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="24" />
        <source>Braille pages to emboss</source>
        <translation>要列印的點字頁</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="26" />
        <source>As the pages are numbered: 3-10, 5- (to the end), 7; in a book t1 for the title page, p1-p2 for the contents</source>
        <translation>依頁面上的頁碼：3-10、5-（到最後）、7；書中 t1 為書名頁，p1-p2 為目錄</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="27" />
        <source>e.g. 3-10, 5-, p1-p2</source>
        <translation>例如 3-10、5-、p1-p2</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="29" />
        <source>Pages:</source>
        <translation>頁：</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="31" />
        <source>Em&amp;boss:</source>
        <translation>列印(&amp;B)：</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="36" />
        <source>To emboss</source>
        <translation>要列印的內容</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="80" />
        <source>Whole document</source>
        <translation>整份文件</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="83" />
        <source>Volume %1 of %2</source>
        <translation>第 %1 冊，共 %2 冊</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="84" />
        <source>Page range</source>
        <translation>頁碼範圍</translation>
    </message>
    <message>
        <location filename="../../widgets/emboss_choice.cpp" line="120" />
        <source>No pages chosen: %1</source>
        <translation>未選擇任何頁：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/emboss_choice.cpp" line="126" />
        <source>Whole document: %n sheet(s)</source>
        <translation><numerusform>整份文件：%n 張</numerusform></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/emboss_choice.cpp" line="128" />
        <source>Volume %1 of %2: %n sheet(s)</source>
        <translation><numerusform>第 %1 冊，共 %2 冊：%n 張</numerusform></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/emboss_choice.cpp" line="133" />
        <source>Pages %1 to %2: %n sheet(s)</source>
        <translation><numerusform>第 %1 頁到第 %2 頁：%n 張</numerusform></translation>
    </message>
</context>
<context>
    <name>tactus::gui::FindReplaceDialog</name>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="23" />
        <source>Find and Replace</source>
        <translation>尋找與取代</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="26" />
        <source>Find</source>
        <translation>尋找</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="28" />
        <source>Replace with</source>
        <translation>取代為</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="31" />
        <source>&amp;Match case</source>
        <translation>大小寫須相符(&amp;M)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="32" />
        <source>&amp;Whole words</source>
        <translation>全字拼寫須相符(&amp;W)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="34" />
        <source>Search result</source>
        <translation>搜尋結果</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="36" />
        <source>F&amp;ind:</source>
        <translation>尋找(&amp;I)：</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="37" />
        <source>Re&amp;place with:</source>
        <translation>取代為(&amp;P)：</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="41" />
        <source>Find &amp;Next</source>
        <translation>找下一個(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="42" />
        <source>Find Pre&amp;vious</source>
        <translation>找上一個(&amp;V)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="43" />
        <source>&amp;Replace</source>
        <translation>取代(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="44" />
        <source>Replace &amp;All</source>
        <translation>全部取代(&amp;A)</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="78" />
        <source>“%1” not found</source>
        <translation>找不到「%1」</translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="83" />
        <source>Found on line %1</source>
        <translation>在第 %1 行找到</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/find_replace.cpp" line="118" />
        <source>%n replaced</source>
        <translation><numerusform>已取代 %n 處</numerusform></translation>
    </message>
</context>
<context>
    <name>tactus::gui::GraphicView</name>
    <message>
        <location filename="../../widgets/document_loader.cpp" line="141" />
        <source>Graphic: %1.</source>
        <translation>圖形：%1。</translation>
    </message>
    <message>
        <location filename="../../widgets/document_loader.cpp" line="145" />
        <source>Labels: %1.</source>
        <translation>標籤：%1。</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/document_loader.cpp" line="148" />
        <source>%n dot(s).</source>
        <comment>on all the graphic's pages</comment>
        <translation><numerusform>%n 點。</numerusform></translation>
    </message>
</context>
<context>
    <name>tactus::gui::LanguageChoice</name>
    <message>
        <location filename="../../widgets/language_choice.cpp" line="31" />
        <source>Language: %1</source>
        <translation>語言：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/language_choice.cpp" line="35" />
        <source>Language: document default</source>
        <translation>語言：文件預設</translation>
    </message>
    <message>
        <location filename="../../widgets/language_choice.cpp" line="41" />
        <source>Language</source>
        <translation>語言</translation>
    </message>
    <message>
        <location filename="../../widgets/language_choice.cpp" line="44" />
        <source>Document default</source>
        <translation>文件預設</translation>
    </message>
    <message>
        <location filename="../../widgets/language_choice.cpp" line="51" />
        <source>The whole &amp;paragraph</source>
        <translation>整個段落(&amp;P)</translation>
    </message>
    <message>
        <location filename="../../widgets/language_choice.cpp" line="54" />
        <source>&amp;Language:</source>
        <translation>語言(&amp;L)：</translation>
    </message>
</context>
<context>
    <name>tactus::gui::MainWindow</name>
    <message>
        <location filename="../../widgets/main_window.cpp" line="82" />
        <location filename="../../widgets/main_window.cpp" line="797" />
        <location filename="../../widgets/main_window.cpp" line="980" />
        <location filename="../../widgets/main_window.cpp" line="1034" />
        <location filename="../../widgets/main_window.cpp" line="1055" />
        <location filename="../../widgets/main_window.cpp" line="1088" />
        <location filename="../../widgets/main_window.cpp" line="1105" />
        <source>Tactus</source>
        <translation>Tactus</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="92" />
        <source>Preview</source>
        <translation>預覽</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="99" />
        <source>Motion</source>
        <translation>運動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="100" />
        <source>Vibration</source>
        <translation>振動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="101" />
        <source>Printer profile</source>
        <translation>印表機設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="106" />
        <source>Printer</source>
        <translation>印表機</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="138" />
        <source>Braille</source>
        <translation>點字</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="140" />
        <source>Braille toolbar</source>
        <translation>點字工具列</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="141" />
        <source>&amp;Table:</source>
        <translation>點字表(&amp;T)：</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="148" />
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="153" />
        <source>Status</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="243" />
        <source>&amp;New</source>
        <translation>新增(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="246" />
        <source>&amp;Open or Import...</source>
        <translation>開啟或匯入(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="247" />
        <source>&amp;Save</source>
        <translation>儲存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="248" />
        <source>Save &amp;As...</source>
        <translation>另存新檔(&amp;A)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="248" />
        <source>Ctrl+Shift+S</source>
        <translation>Ctrl+Shift+S</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="249" />
        <source>Export &amp;BRF...</source>
        <translation>匯出 BRF(&amp;B)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="249" />
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="251" />
        <source>Export &amp;PEF...</source>
        <translation>匯出 PEF(&amp;P)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="251" />
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="253" />
        <source>Boo&amp;k Settings...</source>
        <translation>書籍設定(&amp;K)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="357" />
        <source>Ctrl+Shift+B</source>
        <translation>Ctrl+Shift+B</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="262" />
        <location filename="../../widgets/main_window.cpp" line="1112" />
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="253" />
        <source>Ctrl+Shift+K</source>
        <translation>Ctrl+Shift+K</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="359" />
        <source>Ctrl+Alt+G</source>
        <translation>Ctrl+Alt+G</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="257" />
        <source>Emboss Pictures as &amp;Graphics</source>
        <translation>將圖片列印為觸覺圖形(&amp;G)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="255" />
        <source>Ctrl+Alt+I</source>
        <translation>Ctrl+Alt+I</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="255" />
        <source>Gr&amp;aphic...</source>
        <translation>圖形(&amp;A)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="257" />
        <source>Ctrl+Shift+G</source>
        <translation>Ctrl+Shift+G</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="262" />
        <source>Ctrl+Q</source>
        <translation>Ctrl+Q</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="263" />
        <source>&amp;Undo</source>
        <translation>復原(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="266" />
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="271" />
        <source>Undone: %1</source>
        <translation>已復原：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="273" />
        <source>Redone: %1</source>
        <translation>已重做：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="275" />
        <source>&amp;Find and Replace...</source>
        <translation>尋找與取代(&amp;F)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="281" />
        <source>Find &amp;Next</source>
        <translation>找下一個(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="283" />
        <source>Go to &amp;print text</source>
        <translation>移到明眼字(&amp;P)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="283" />
        <source>Ctrl+1</source>
        <translation>Ctrl+1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="285" />
        <source>Go to &amp;braille</source>
        <translation>移到點字(&amp;B)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="285" />
        <source>Ctrl+2</source>
        <translation>Ctrl+2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="287" />
        <source>Go to pre&amp;view</source>
        <translation>移到預覽(&amp;V)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="287" />
        <source>Ctrl+3</source>
        <translation>Ctrl+3</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="292" />
        <source>Choose braille &amp;table</source>
        <translation>選擇點字表(&amp;T)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="292" />
        <source>Ctrl+T</source>
        <translation>Ctrl+T</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="296" />
        <source>Go to &amp;motion</source>
        <translation>移到運動(&amp;M)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="296" />
        <source>Ctrl+4</source>
        <translation>Ctrl+4</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="300" />
        <source>Go to vibratio&amp;n</source>
        <translation>移到振動(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="300" />
        <source>Ctrl+5</source>
        <translation>Ctrl+5</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="304" />
        <source>Go to printer pro&amp;file</source>
        <translation>移到印表機設定檔(&amp;F)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="304" />
        <source>Ctrl+6</source>
        <translation>Ctrl+6</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="308" />
        <source>Go to p&amp;rinter</source>
        <translation>前往印表機(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="308" />
        <source>Ctrl+7</source>
        <translation>Ctrl+7</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="313" />
        <source>&amp;Emboss</source>
        <translation>列印點字(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="313" />
        <source>Ctrl+P</source>
        <translation>Ctrl+P</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="314" />
        <source>&amp;Keyboard Shortcuts</source>
        <translation>鍵盤快速鍵(&amp;K)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="314" />
        <source>Ctrl+F1</source>
        <translation>Ctrl+F1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="316" />
        <source>&amp;About Tactus</source>
        <translation>關於 Tactus(&amp;A)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="316" />
        <source>Shift+F1</source>
        <translation>Shift+F1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="319" />
        <source>Open the menu bar</source>
        <translation>開啟選單列</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="337" />
        <source>&amp;Body text</source>
        <translation>內文(&amp;B)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="337" />
        <source>Ctrl+Alt+0</source>
        <translation>Ctrl+Alt+0</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="340" />
        <source>Heading &amp;%1</source>
        <translation>標題 %1(&amp;%1)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="340" />
        <source>Ctrl+Alt+%1</source>
        <translation>Ctrl+Alt+%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="342" />
        <source>B&amp;ulleted list</source>
        <translation>項目符號清單(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="342" />
        <source>Ctrl+Alt+L</source>
        <translation>Ctrl+Alt+L</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="344" />
        <source>&amp;Numbered list</source>
        <translation>編號清單(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="344" />
        <source>Ctrl+Alt+N</source>
        <translation>Ctrl+Alt+N</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="346" />
        <source>&amp;Quotation</source>
        <translation>引文(&amp;Q)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="346" />
        <source>Ctrl+Alt+Q</source>
        <translation>Ctrl+Alt+Q</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="348" />
        <source>&amp;Page break</source>
        <translation>分頁(&amp;P)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="348" />
        <source>Ctrl+Return</source>
        <translation>Ctrl+Return</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="349" />
        <source>Bol&amp;d</source>
        <translation>粗體(&amp;D)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="349" />
        <source>Ctrl+B</source>
        <translation>Ctrl+B</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="351" />
        <source>&amp;Italic</source>
        <translation>斜體(&amp;I)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="351" />
        <source>Ctrl+I</source>
        <translation>Ctrl+I</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="353" />
        <source>Und&amp;erline</source>
        <translation>底線(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="353" />
        <source>Ctrl+U</source>
        <translation>Ctrl+U</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="355" />
        <source>&amp;Raised</source>
        <translation>上標(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="357" />
        <source>&amp;Lowered</source>
        <translation>下標(&amp;L)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="359" />
        <source>Lan&amp;guage...</source>
        <translation>語言(&amp;G)...</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="370" />
        <source>Bo&amp;x</source>
        <translation>方框(&amp;X)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="370" />
        <source>Ctrl+Alt+X</source>
        <translation>Ctrl+Alt+X</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="371" />
        <source>No&amp;te</source>
        <translation>註解(&amp;T)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="373" />
        <source>Note %1: type its text</source>
        <translation>註解 %1：請輸入內容</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="375" />
        <source>Show &amp;codes</source>
        <translation>顯示代碼(&amp;C)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="378" />
        <source>Ctrl+Alt+C</source>
        <translation>Ctrl+Alt+C</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="379" />
        <source>Show the print text's Markdown codes instead of its styles</source>
        <translation>以 Markdown 代碼顯示明眼字，而不是其樣式</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="389" />
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="391" />
        <source>Open &amp;Recent</source>
        <translation>最近開啟(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="400" />
        <source>&amp;Edit</source>
        <translation>編輯(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="405" />
        <source>St&amp;yles</source>
        <translation>樣式(&amp;Y)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="410" />
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="419" />
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="464" />
        <source>Translating with %1</source>
        <translation>正在以 %1 轉譯</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="471" />
        <source>Cannot use table %1: %2</source>
        <translation>無法使用點字表 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="476" />
        <location filename="../../widgets/main_window.cpp" line="725" />
        <source>Braille table: %1</source>
        <translation>點字表：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="486" />
        <source>the text is mostly in Latin letters; for English, Unified English Braille (%1) suits it</source>
        <translation>文字大多是拉丁字母；英文適合用統一英文點字（%1）</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="488" />
        <source>the text is mostly Traditional Chinese; Taiwanese bopomofo braille (%1) suits it</source>
        <translation>文字大多是繁體中文；適合用台灣注音點字（%1）</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="489" />
        <source>the text is mostly Simplified Chinese; Chinese double-phonic braille (%1) suits it</source>
        <translation>文字大多是簡體中文；適合用中文雙拼點字（%1）</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="492" />
        <source>Warning: the table %1 does not suit all of this text (%2). Ctrl+T chooses another table.</source>
        <translation>警告：點字表 %1 不適用於這份文字的全部內容（%2）。按 Ctrl+T 選擇其他點字表。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="507" />
        <source>Pictures not embossed as graphics: %1</source>
        <translation>圖片未列印為觸覺圖形：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="524" />
        <source>Pictures are embossed as graphics, each after its description</source>
        <translation>圖片將列印為觸覺圖形，各接在其描述之後</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="525" />
        <source>Pictures are embossed as their descriptions only</source>
        <translation>圖片只列印其描述</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="531" />
        <location filename="../../widgets/main_window.cpp" line="536" />
        <source>Insert graphic</source>
        <translation>插入圖形</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="532" />
        <source>Pictures (*.svg *.png *.jpg *.jpeg)</source>
        <translation>圖片 (*.svg *.png *.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="537" />
        <source>Description of %1 (what a reader who cannot see it needs to know):</source>
        <translation>%1 的描述（看不見圖片的讀者需要知道的內容）：</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="549" />
        <source>Not inserted: %1 needs a description, which is what a braille reader reads of it</source>
        <translation>未插入：%1 需要描述，點字讀者讀到的就是這段描述</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="558" />
        <source>Cannot insert %1: %2</source>
        <translation>無法插入 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="562" />
        <source>Cannot insert %1: only a document (not a text file or a graphic) holds pictures</source>
        <translation>無法插入 %1：只有文件（不是純文字檔或圖形）能含有圖片</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="566" />
        <source>Graphic %1 inserted: %2</source>
        <translation>已插入圖形 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="583" />
        <source>Cannot lay out %1 again: %2</source>
        <translation>無法重新排版 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="585" />
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="609" />
        <source>Open or import</source>
        <translation>開啟或匯入</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="610" />
        <source>Documents (*.md *.markdown *.txt *.docx *.odt *.brf *.pef *.svg *.png *.jpg *.jpeg);;Tactile graphics (*.svg *.png *.jpg *.jpeg);;All files (*)</source>
        <translation>文件 (*.md *.markdown *.txt *.docx *.odt *.brf *.pef *.svg *.png *.jpg *.jpeg);;觸覺圖形 (*.svg *.png *.jpg *.jpeg);;所有檔案 (*)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="617" />
        <source>Opening %1</source>
        <translation>正在開啟 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="632" />
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="644" />
        <source>%1 percent</source>
        <translation>百分之 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="674" />
        <source>Cancelled; the document is unchanged</source>
        <translation>已取消，文件未變更</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="679" />
        <source>Cannot open %1: %2</source>
        <translation>無法開啟 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="680" />
        <source>the document</source>
        <translation>文件</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="704" />
        <source>Opened %1: %n sheet(s)</source>
        <translation><numerusform>已開啟 %1：%n 張</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="707" />
        <source>%1. %2</source>
        <comment>a message, then what the graphic is</comment>
        <translation>%1。%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="710" />
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="719" />
        <source>%n line(s) could not be translated; they are left out of the braille</source>
        <translation><numerusform>有 %n 行無法轉譯，未列入點字</numerusform></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="746" />
        <source>Graphic %1 | %n sheet(s)</source>
        <translation><numerusform>圖形 %1 | %n 張</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="754" />
        <source>Sheet %1 of %2%3 | line %4 | cell %5 | print page %6</source>
        <translation>第 %1 張，共 %2 張%3 | 第 %4 行 | 第 %5 方 | 原書第 %6 頁</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="757" />
        <source>, back</source>
        <translation>，背面</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="757" />
        <source>, front</source>
        <translation>，正面</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="772" />
        <location filename="../../widgets/main_window.cpp" line="981" />
        <location filename="../../widgets/main_window.cpp" line="992" />
        <location filename="../../widgets/main_window.cpp" line="1162" />
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="777" />
        <source>%1 — Tactus</source>
        <translation>%1 — Tactus</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="807" />
        <source>Cannot save %1: a tactile graphic is kept in its own file; emboss or plan it, or open a document to save</source>
        <translation>無法儲存 %1：觸覺圖形保存在它自己的檔案中；請列印或規劃它，或開啟文件再儲存</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="820" />
        <source>Save as</source>
        <translation>另存新檔</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="883" />
        <source>Saved %1</source>
        <translation>已儲存 %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="885" />
        <source>with %n picture file(s) beside it</source>
        <translation><numerusform>並在旁邊存入 %n 個圖片檔</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1093" />
        <source>Saving would lose pictures</source>
        <translation>儲存會失去圖片</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1158" />
        <source>untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="893" />
        <source>PEF (*.pef)</source>
        <translation>PEF (*.pef)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="893" />
        <source>Braille ASCII (*.brf)</source>
        <translation>點字 ASCII (*.brf)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="895" />
        <source>Export</source>
        <translation>匯出</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="917" />
        <source>Cannot export %1: %2</source>
        <translation>無法匯出 %1：%2</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="926" />
        <source>Exported %1 (%n sheet(s))</source>
        <translation><numerusform>已匯出 %1（%n 張）</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="933" />
        <source>Print preview to PDF</source>
        <translation>將預覽列印為 PDF</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="934" />
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="945" />
        <source>Wrote proof %1</source>
        <translation>已寫出校稿 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="980" />
        <source>Save the changes to %1?</source>
        <translation>要儲存對 %1 的變更嗎？</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1106" />
        <source>%1 is being embossed. Quit anyway?</source>
        <translation>%1 正在列印。仍要結束嗎？</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1107" />
        <source>The job stays in the print queue. The sheet in the embosser now is discarded; the rest is embossed when Tactus or tactus-cli serve runs printer %1 again.</source>
        <translation>工作會留在列印佇列中。點字印表機中目前這張紙會作廢；其餘部分會在 Tactus 或 tactus-cli serve 再次執行印表機 %1 時列印。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1113" />
        <source>&amp;Keep embossing</source>
        <translation>繼續列印(&amp;K)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="993" />
        <source>The printer's page is too small for the pages of %1. Lay the braille out again on the printer's page?</source>
        <translation>印表機的頁面放不下 %1 的頁面。要在印表機的頁面上重新排版點字嗎？</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1007" />
        <source>The pages of %1 are %2 cells by %3 lines; the printer's page holds %4 cells by %5 lines.</source>
        <translation>%1 的頁面為每行 %2 方、每頁 %3 行；印表機的頁面只容納每行 %4 方、每頁 %5 行。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1016" />
        <source>volume %1, %2 cells by %3 lines</source>
        <translation>第 %1 冊，每行 %2 方、每頁 %3 行</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1016" />
        <source>volume %1, %2 cells by %3 lines, too large</source>
        <translation>第 %1 冊，每行 %2 方、每頁 %3 行，太大</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1020" />
        <source>The pages of %1 differ by volume: %2. The printer's page holds %3 cells by %4 lines.</source>
        <translation>%1 各冊的頁面大小不同：%2。印表機的頁面只容納每行 %3 方、每頁 %4 行。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1186" />
        <source>Cannot send %1: %2</source>
        <translation>無法送出 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1021" />
        <source>; </source>
        <translation>；</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1026" />
        <source>Nothing has been embossed or exported. Reflow lays the braille out again on the printer's page, so its lines and pages change. Stop leaves it as it is; choose a printer whose page is large enough.</source>
        <translation>尚未列印或匯出任何內容。「重新排版」會在印表機的頁面上重新排版點字，行與頁都會改變。「停止」則保持原樣；請選擇頁面夠大的印表機。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="124" />
        <source>The document cannot be laid out for this printer's page: %1</source>
        <translation>無法依此印表機的頁面排版文件：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="856" />
        <source>Cannot save %1: %2</source>
        <translation>無法儲存 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1050" />
        <source>%1 cannot be saved in its encoding, %2. Save it as UTF-8?</source>
        <translation>%1 無法以原本的編碼 %2 儲存。要改存成 UTF-8 嗎？</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1051" />
        <source>At line:column %1, %2. Nothing has been saved. UTF-8 holds every character, but programs that expect %3 may show it wrongly. Cancel leaves the file as it is; remove the character to keep %3.</source>
        <translation>位於 行:欄 %1，%2。尚未儲存任何內容。UTF-8 能容納所有字元，但預期 %3 的程式可能顯示錯誤。按「取消」保留檔案原狀；刪除該字元即可維持 %3。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1058" />
        <source>A character does not fit the file's encoding</source>
        <translation>有字元不符合檔案的編碼</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1060" />
        <source>Save as &amp;UTF-8</source>
        <translation>存成 UTF-8(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1061" />
        <source>Save the whole file as UTF-8 from now on</source>
        <translation>此後整個檔案都存成 UTF-8</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1062" />
        <location filename="../../widgets/main_window.cpp" line="1097" />
        <source>Save nothing</source>
        <translation>不儲存任何內容</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1063" />
        <source>Not saved: %1 has a character that %2 cannot hold</source>
        <translation>未儲存：%1 含有 %2 無法容納的字元</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1037" />
        <source>The printer's page is too small</source>
        <translation>印表機的頁面太小</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1039" />
        <source>&amp;Reflow</source>
        <translation>重新排版(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1041" />
        <source>&amp;Stop</source>
        <translation>停止(&amp;S)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1040" />
        <source>Lay the braille out again on the printer's page and go on</source>
        <translation>在印表機的頁面上重新排版點字並繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1041" />
        <source>Emboss or export nothing</source>
        <translation>不列印也不匯出</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1043" />
        <source>Stopped: nothing was embossed or exported (the printer's page is too small for %1)</source>
        <translation>已停止：未列印或匯出任何內容（印表機的頁面放不下 %1）</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="737" />
        <source>The braille's own pages, sections and volumes are kept again</source>
        <translation>已恢復保留點字原有的頁面、段落與分冊</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="355" />
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="371" />
        <source>Ctrl+Alt+E</source>
        <translation>Ctrl+Alt+E</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="738" />
        <source>The braille is laid out again on the printer's page: its own pages, sections and volumes are kept only while it holds nothing but braille rows that fit the page</source>
        <translation>點字已在印表機的頁面上重新排版：只有在文件只含放得下頁面的點字行時，才會保留原有的頁面、段落與分冊</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="1089" />
        <source>%1 cannot keep %n of the document's pictures. Save anyway?</source>
        <translation><numerusform>%1 無法保留文件中的 %n 張圖片。仍要儲存嗎？</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1090" />
        <source>Nothing has been saved. In %1 each of these pictures would be its description only. Cancel saves nothing; a DOCX or ODT file keeps every picture.</source>
        <translation>尚未儲存任何內容。在 %1 中，這些圖片都只會剩下描述文字。按「取消」不儲存任何內容；DOCX 或 ODT 檔會保留每張圖片。</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1095" />
        <source>&amp;Save Without Them</source>
        <translation>不含圖片儲存(&amp;S)</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1096" />
        <source>Save with the pictures' descriptions only</source>
        <translation>儲存時只保留圖片的描述</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="1098" />
        <source>Not saved: %1 cannot keep %n picture(s)</source>
        <translation><numerusform>未儲存：%1 無法保留 %n 張圖片</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1178" />
        <source>Cannot send %1 to a CUPS queue: a tactile graphic is embossed on a device (choose it in the printer panel)</source>
        <translation>無法將 %1 送到 CUPS 佇列：觸覺圖形須在點字印表機上列印（請在印表機面板選擇裝置）</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1254" />
        <source>Cannot plan the job: %1</source>
        <translation>無法規劃工作：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1287" />
        <location filename="../../widgets/main_window.cpp" line="1296" />
        <source>Cannot read the autosaved copy %1: %2</source>
        <translation>無法讀取自動儲存的副本 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1320" />
        <source>Recovered</source>
        <translation>已復原</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1325" />
        <source>Recovered unsaved changes to %1</source>
        <translation>已復原 %1 未儲存的變更</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1338" />
        <source>Keyboard Shortcuts</source>
        <translation>鍵盤快速鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1342" />
        <source>Shortcuts</source>
        <translation>快速鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1344" />
        <source>Action</source>
        <translation>動作</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1344" />
        <source>Shortcut</source>
        <translation>快速鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1373" />
        <source>Braille pane: dots 1 2 3 4 5 6 (chord, released together)</source>
        <translation>點字窗格：第 1 2 3 4 5 6 點（同時按下、一起放開）</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1373" />
        <source>F D S J K L</source>
        <translation>F D S J K L</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1374" />
        <source>Braille pane: blank cell / erase cell</source>
        <translation>點字窗格：空方 / 刪除點字方</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1374" />
        <source>Space / Backspace, Delete</source>
        <translation>空白鍵 / 退格鍵、刪除鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1375" />
        <source>Preview: move between cells / lines</source>
        <translation>預覽：在點字方 / 行之間移動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1375" />
        <source>Arrow keys</source>
        <translation>方向鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1376" />
        <source>Preview: turn to the other side</source>
        <translation>預覽：翻到另一面</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1376" />
        <source>Space</source>
        <translation>空白鍵</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1377" />
        <source>Preview: previous / next sheet</source>
        <translation>預覽：上一張 / 下一張</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1377" />
        <source>PgUp / PgDown</source>
        <translation>PgUp / PgDown</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1378" />
        <source>Move between panes</source>
        <translation>在窗格之間移動</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1378" />
        <source>Tab / Shift+Tab</source>
        <translation>Tab / Shift+Tab</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="1392" />
        <source>Book settings: about %n sheet(s) per volume</source>
        <translation><numerusform>書籍設定：每冊約 %n 張</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1397" />
        <source>About Tactus</source>
        <translation>關於 Tactus</translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="1398" />
        <source>&lt;p&gt;&lt;b&gt;Tactus %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Braille editor and embosser print manager.&lt;/p&gt;&lt;p&gt;Licensed under the GNU GPL, version 3 or later.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Tactus %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;點字編輯器與點字印表機管理程式。&lt;/p&gt;&lt;p&gt;依 GNU GPL 第 3 版或更新版本授權。&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>tactus::gui::MotionView</name>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="65" />
        <source>Sheet</source>
        <translation>紙張</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="67" />
        <source>Pass</source>
        <translation>行程</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="69" />
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="70" />
        <source>Position (mm)</source>
        <translation>位置 (mm)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="70" />
        <source>Velocity (mm/s)</source>
        <translation>速度 (mm/s)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="70" />
        <source>Acceleration (mm/s²)</source>
        <translation>加速度 (mm/s²)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="71" />
        <source>Jerk (mm/s³)</source>
        <translation>加加速度 (mm/s³)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="72" />
        <source>Compare prof&amp;ile shapes</source>
        <translation>比較運動曲線(&amp;I)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="76" />
        <source>&amp;Sheet:</source>
        <translation>紙張(&amp;S)：</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="77" />
        <source>P&amp;ass:</source>
        <translation>行程(&amp;A)：</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="78" />
        <source>Sho&amp;w:</source>
        <translation>顯示(&amp;W)：</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="85" />
        <source>Carriage motion chart</source>
        <translation>字車運動圖</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="95" />
        <source>Time estimates</source>
        <translation>時間估計</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="101" />
        <source>Profile shapes on this pass</source>
        <translation>此行程的各種運動曲線</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="102" />
        <source>Profile shape</source>
        <translation>運動曲線</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="102" />
        <source>Pass time</source>
        <translation>行程時間</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="102" />
        <source>Versus lower bound</source>
        <translation>相對於下限</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="108" />
        <source>Strikes of this pass</source>
        <translation>此行程的擊點</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="109" />
        <location filename="../../widgets/motion_view.cpp" line="221" />
        <source>Time (ms)</source>
        <translation>時間 (ms)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="109" />
        <source>Carriage (mm)</source>
        <translation>字車 (mm)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="109" />
        <source>Side</source>
        <translation>面</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="109" />
        <source>Residual (µm)</source>
        <translation>殘留振動 (µm)</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="154" />
        <source>No plan yet</source>
        <translation>尚未規劃</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="162" />
        <source>Sheet %1: %2 (lower bound %3, %4). Document, %5 sheets: %6 (lower bound %7, %8).</source>
        <translation>第 %1 張：%2（下限 %3，%4）。整份文件 %5 張：%6（下限 %7，%8）。</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="170" />
        <source>This sheet is blank.</source>
        <translation>這張是空白的。</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="174" />
        <source>Pass %1 (%2, %3 strikes): %4, lower bound %5.</source>
        <translation>行程 %1（%2，%3 個擊點）：%4，下限 %5。</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="176" />
        <location filename="../../widgets/motion_view.cpp" line="230" />
        <source>front</source>
        <translation>正面</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="176" />
        <location filename="../../widgets/motion_view.cpp" line="230" />
        <source>back</source>
        <translation>背面</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="183" />
        <location filename="../../widgets/motion_view.cpp" line="210" />
        <source>Planned (auto-tuned)</source>
        <translation>規劃（自動調校）</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="187" />
        <source>Strikes</source>
        <translation>擊點</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="200" />
        <source>Trapezoid</source>
        <translation>梯形</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="201" />
        <source>S-curve (smoothstep)</source>
        <translation>S 曲線（smoothstep）</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="202" />
        <source>Jerk-limited (7 segments)</source>
        <translation>限制加加速度（7 段）</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="223" />
        <source>Sheet %1, pass %2</source>
        <translation>第 %1 張，行程 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/motion_view.cpp" line="235" />
        <source>%1 against time for sheet %2, pass %3: %4 strikes over %5; from %6 to %7. The strike table lists the same data.</source>
        <translation>第 %2 張行程 %3 的%1對時間：%4 個擊點，歷時 %5；範圍 %6 到 %7。擊點表列出相同資料。</translation>
    </message>
</context>
<context>
    <name>tactus::gui::PreviewPanel</name>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="22" />
        <source>Preview scroll area</source>
        <translation>預覽捲動區</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="38" />
        <source>Fr&amp;ont</source>
        <translation>正面(&amp;O)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="38" />
        <source>Ctrl+Alt+F</source>
        <translation>Ctrl+Alt+F</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="39" />
        <source>Bac&amp;k</source>
        <translation>背面(&amp;K)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="39" />
        <source>Ctrl+Alt+B</source>
        <translation>Ctrl+Alt+B</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="40" />
        <source>Front &amp;and back</source>
        <translation>正面與背面(&amp;A)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="40" />
        <source>Ctrl+Alt+A</source>
        <translation>Ctrl+Alt+A</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="46" />
        <source>Pr&amp;evious sheet</source>
        <translation>上一張(&amp;E)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="46" />
        <source>Ctrl+PgUp</source>
        <translation>Ctrl+PgUp</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="47" />
        <source>Ne&amp;xt sheet</source>
        <translation>下一張(&amp;X)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="47" />
        <source>Ctrl+PgDown</source>
        <translation>Ctrl+PgDown</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="48" />
        <source>Previou&amp;s volume</source>
        <translation>上一冊(&amp;S)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="48" />
        <source>Ctrl+Alt+PgUp</source>
        <translation>Ctrl+Alt+PgUp</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="49" />
        <source>Next vo&amp;lume</source>
        <translation>下一冊(&amp;L)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="49" />
        <source>Ctrl+Alt+PgDown</source>
        <translation>Ctrl+Alt+PgDown</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="50" />
        <source>Zoom &amp;in</source>
        <translation>放大(&amp;I)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="51" />
        <source>Zoom o&amp;ut</source>
        <translation>縮小(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="52" />
        <source>&amp;High contrast</source>
        <translation>高對比(&amp;H)</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="52" />
        <source>Ctrl+Alt+H</source>
        <translation>Ctrl+Alt+H</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="54" />
        <source>Print preview to P&amp;DF...</source>
        <translation>將預覽列印為 PDF(&amp;D)...</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="54" />
        <source>Ctrl+Alt+P</source>
        <translation>Ctrl+Alt+P</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="72" />
        <source>Preview</source>
        <translation>預覽</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="74" />
        <source>Preview controls</source>
        <translation>預覽控制</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="83" />
        <source>Volume</source>
        <translation>冊</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="84" />
        <source>Go to volume (%1, %2)</source>
        <translation>前往某一冊（%1、%2）</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="91" />
        <source>View</source>
        <translation>檢視</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="93" />
        <source>Preview view controls</source>
        <translation>預覽顯示控制</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="100" />
        <source>Preview status</source>
        <translation>預覽狀態</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="136" />
        <source>Volume %1 of %2</source>
        <translation>第 %1 冊，共 %2 冊</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="154" />
        <source>Volume %1 of %2 is the last</source>
        <translation>第 %1 冊（共 %2 冊）是最後一冊</translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="162" />
        <location filename="../../widgets/preview_panel.cpp" line="170" />
        <source>%1; %2</source>
        <comment>where in the book; the sheet</comment>
        <translation>%1；%2</translation>
    </message>
</context>
<context>
    <name>tactus::gui::PrintPane</name>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="188" />
        <source>Print text</source>
        <translation>明眼字</translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="212" />
        <source>What the tactile graphic is: its title, description, labels and dots</source>
        <translation>這個觸覺圖形的內容：標題、描述、標籤與點數</translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="214" />
        <source>One paragraph per line: # for headings, - for list items, *italic*, **bold**</source>
        <translation>每行一段：# 為標題、- 為清單項目、*斜體*、**粗體**</translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="215" />
        <source>The print text with its styles: headings, lists, tables, emphasis; Styles menu to change them</source>
        <translation>帶樣式的明眼字：標題、清單、表格、強調；用「樣式」功能表變更</translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="213" />
        <source>The text file's lines as written: a blank line between paragraphs, a form feed starts a print page</source>
        <translation>文字檔的各行照原樣：段落之間空一行，換頁字元開始新的印刷頁</translation>
    </message>
</context>
<context>
    <name>tactus::gui::PrinterPanel</name>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="155" />
        <source>Embosser</source>
        <translation>點字印表機</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="157" />
        <source>The built-in simulator, serial ports with their USB descriptions, HID bridges and parallel ports, and the Tactus queues of the CUPS servers this computer sees, marked network queue; or type a device string such as pty:/dev/pts/3, serial:/dev/ttyUSB0?baud=57600 or ipp://server/printers/Embosser</source>
        <translation>內建模擬器、序列埠（含 USB 說明）、HID 轉接器與平行埠，以及本電腦看得到的 CUPS 伺服器上的 Tactus 佇列（標為網路佇列）；也可以輸入裝置字串，例如 pty:/dev/pts/3、serial:/dev/ttyUSB0?baud=57600 或 ipp://server/printers/Embosser</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="162" />
        <source>&amp;Refresh</source>
        <translation>重新整理(&amp;R)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="163" />
        <location filename="../../widgets/printer_panel.cpp" line="532" />
        <location filename="../../widgets/printer_panel.cpp" line="584" />
        <source>&amp;Connect</source>
        <translation>連線(&amp;C)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="167" />
        <location filename="../../widgets/printer_panel.cpp" line="900" />
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="169" />
        <source>Controller status</source>
        <translation>控制器狀態</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="174" />
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="179" />
        <source>Job queue</source>
        <translation>工作佇列</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="180" />
        <source>The print spool's jobs, from this window, tactus-cli and the network</source>
        <translation>列印佇列中的工作，來自本視窗、tactus-cli 與網路</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="181" />
        <source>Document</source>
        <translation>文件</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="181" />
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="181" />
        <source>Progress</source>
        <translation>進度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="181" />
        <source>Sheet</source>
        <translation>紙張</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="181" />
        <source>Job</source>
        <translation>工作</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="181" />
        <source>Printer</source>
        <translation>印表機</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="191" />
        <source>&amp;Pause</source>
        <translation>暫停(&amp;P)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="192" />
        <source>Res&amp;ume</source>
        <translation>繼續(&amp;U)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="193" />
        <source>Ca&amp;ncel job</source>
        <translation>取消工作(&amp;N)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="199" />
        <source>Braille page to resume from</source>
        <translation>從哪一個點字頁繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="200" />
        <source>Resume from pa&amp;ge</source>
        <translation>從指定頁繼續(&amp;G)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="204" />
        <source>Link log</source>
        <translation>連線紀錄</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="209" />
        <source>Simulator faults (built-in simulator)</source>
        <translation>模擬器故障（內建模擬器）</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="219" />
        <source>Paper out</source>
        <translation>缺紙</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="220" />
        <source>The feeder runs empty; the simulated operator loads paper 5 seconds later</source>
        <translation>送紙器沒紙了；模擬的操作員會在 5 秒後補紙</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="222" />
        <source>Pull the cable</source>
        <translation>拔除纜線</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="223" />
        <source>The cable is out for 5 seconds; the link reconnects</source>
        <translation>纜線拔除 5 秒；連線會重新建立</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="224" />
        <source>Line noise</source>
        <translation>線路雜訊</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="225" />
        <source>For 2 seconds, 1 byte in 100 is lost, changed or doubled; the link sends again</source>
        <translation>持續 2 秒，每 100 個位元組中有 1 個遺失、改變或重複；連線會重新傳送</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="227" />
        <source>Controller reset</source>
        <translation>控制器重設</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="228" />
        <source>A watchdog reset: the controller keeps its place and the job continues</source>
        <translation>看門狗重設：控制器記得目前位置，工作繼續進行</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="234" />
        <source>The plan's own speed</source>
        <translation>依列印計畫的實際速度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="235" />
        <source>10 times faster</source>
        <translation>快 10 倍</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="236" />
        <source>As fast as the computer can</source>
        <translation>以電腦能達到的最快速度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="237" />
        <source>Simulator speed</source>
        <translation>模擬器速度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="239" />
        <source>How fast the built-in simulator embosses: at the plan's own speed, as the embosser would, or faster. It sets the speed option of the device string, for example sim?speed=10</source>
        <translation>內建模擬器的列印速度：依列印計畫的實際速度（與點字印表機相同），或更快。它會設定裝置字串的 speed 選項，例如 sim?speed=10</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="241" />
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="248" />
        <source>E&amp;mbosser:</source>
        <translation>點字印表機(&amp;M)：</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="269" />
        <source>Lin&amp;k log (for technicians):</source>
        <translation>連線紀錄（技術人員用）(&amp;K)：</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="324" />
        <source>Built-in simulated embosser</source>
        <translation>內建模擬點字印表機</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="327" />
        <source>The built-in simulated embosser, on this computer</source>
        <translation>內建的模擬點字印表機，在本電腦上</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="328" />
        <source>An embosser on a cable to this computer</source>
        <translation>以纜線連接本電腦的點字印表機</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="331" />
        <source>Listing devices: %1</source>
        <translation>列出裝置：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="70" />
        <source>Network queue %1 on %2</source>
        <translation>網路佇列 %1（位於 %2）</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="75" />
        <source>Network queue %1 on the CUPS server %2</source>
        <translation>網路佇列 %1，位於 CUPS 伺服器 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="78" />
        <source>A Tactus queue on another computer: the document is sent there over the network and laid out with that embosser's profile</source>
        <translation>另一台電腦上的 Tactus 佇列：文件經網路送到那裡，並依該點字印表機的設定檔排版</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/printer_panel_queues.cpp" line="85" />
        <source>%n Tactus queue(s) found on CUPS servers</source>
        <translation><numerusform>在 CUPS 伺服器上找到 %n 個 Tactus 佇列</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="358" />
        <source>The built-in simulator will run as %1 (%2); it takes effect at the next Connect or job</source>
        <translation>內建模擬器將以 %1 執行（%2）；於下次連線或下一個工作時生效</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="370" />
        <source>%1 times faster</source>
        <translation>快 %1 倍</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="393" />
        <source>No place for the print queue: set TACTUS_SPOOL_DB or HOME.</source>
        <translation>沒有地方存放列印佇列：請設定 TACTUS_SPOOL_DB 或 HOME。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="398" />
        <source>Cannot open the print queue: %1</source>
        <translation>無法開啟列印佇列：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="408" />
        <source>“%1” is not a device Tactus can open: %2. Examples: sim, serial:/dev/ttyUSB0?baud=57600, pty:/dev/pts/3, hid:10c4:ea80, lpt:/dev/parport0.</source>
        <translation>「%1」不是 Tactus 能開啟的裝置：%2。範例：sim、serial:/dev/ttyUSB0?baud=57600、pty:/dev/pts/3、hid:10c4:ea80、lpt:/dev/parport0。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="419" />
        <source>Cannot set up a printer for %1: %2</source>
        <translation>無法為 %1 設定印表機：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="423" />
        <source>Set up printer %1 on %2 with the profile being edited</source>
        <translation>已在 %2 上設定印表機 %1，使用正在編輯的設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="430" />
        <source>Cannot give printer %1 the profile being edited: %2</source>
        <translation>無法將正在編輯的設定檔套用到印表機 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="434" />
        <source>Printer %1 now uses the profile being edited</source>
        <translation>印表機 %1 現在使用正在編輯的設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="450" />
        <source>Printer %1 is run by %2: this window shows its jobs</source>
        <translation>印表機 %1 由 %2 執行：本視窗顯示它的工作</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="461" />
        <source>Printer %1: %2; this window shows its jobs</source>
        <translation>印表機 %1：%2；本視窗顯示它的工作</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="473" />
        <source>This window runs printer %1</source>
        <translation>本視窗執行印表機 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="483" />
        <source>This window no longer runs printer %1</source>
        <translation>本視窗不再執行印表機 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="488" />
        <source>%1 is a CUPS queue: there is nothing to connect to. Ctrl+P sends the document to it.</source>
        <translation>%1 是 CUPS 佇列，不需要連線。按 Ctrl+P 即可將文件送過去。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="501" />
        <source>Connecting to %1</source>
        <translation>正在連線到 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="513" />
        <source>Cannot connect to %1: %2. Check that it is switched on and plugged in, then try again.</source>
        <translation>無法連線到 %1：%2。請確認電源已開啟且纜線已接好，然後再試一次。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="106" />
        <source>“%1” is not a CUPS queue: %2</source>
        <translation>「%1」不是 CUPS 佇列：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="118" />
        <source>Cannot send %1: cannot write a copy to send (%2)</source>
        <translation>無法送出 %1：無法寫入要送出的副本（%2）</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="145" />
        <source>Sending %1 to %2 (%3)</source>
        <translation>正在將 %1 送到 %2（%3）</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="146" />
        <source>Sending %1 to %2</source>
        <translation>正在將 %1 送到 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="173" />
        <source>Sent %1 to %2 as job %3</source>
        <translation>已將 %1 送到 %2，工作 %3</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="180" />
        <source>Embossing %1 on %2</source>
        <translation>正在以 %2 列印 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="183" />
        <source>%1 waits on %2: %3</source>
        <translation>%1 在 %2 等待中：%3</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/printer_panel_queues.cpp" line="189" />
        <source>%1: %n sheet(s) embossed</source>
        <translation><numerusform>%1：已列印 %n 張</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="194" />
        <source>Job %1 on %2: %3</source>
        <translation>%2 的工作 %1：%3</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="205" />
        <source>%1: the job on %2 can no longer be followed: %3</source>
        <translation>%1：無法再追蹤 %2 上的工作：%3</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="206" />
        <source>%1 was not sent to %2: %3</source>
        <translation>%1 未送到 %2：%3</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="219" />
        <source>Embossed %1 on %2</source>
        <translation>已以 %2 列印 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="221" />
        <source>%1 cancelled on %2</source>
        <translation>%1 已在 %2 取消</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="222" />
        <source>%1 cancelled on %2: %3</source>
        <translation>%1 已在 %2 取消：%3</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="224" />
        <source>%1 stopped on %2: %3</source>
        <translation>%1 已在 %2 停止：%3</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="678" />
        <source>%1 paused</source>
        <translation>%1 已暫停</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="680" />
        <source>%1 resumed</source>
        <translation>%1 已繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="790" />
        <location filename="../../widgets/printer_panel.cpp" line="793" />
        <source>sending</source>
        <translation>傳送中</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="793" />
        <source>not sent</source>
        <translation>未送出</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="794" />
        <source>cancelling</source>
        <translation>取消中</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="803" />
        <source>Progress of the sheet in hand of %1</source>
        <translation>%1 目前這張的進度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="856" />
        <location filename="../../widgets/printer_panel.cpp" line="893" />
        <source>job %1</source>
        <translation>工作 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="861" />
        <source>job %1: </source>
        <translation>工作 %1：</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="869" />
        <source>%1 The printer is running again.</source>
        <translation>%1 印表機已恢復運作。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="893" />
        <source>%1 goes on: the printer is running again</source>
        <translation>%1 繼續進行：印表機已恢復運作</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="904" />
        <source>run by this window</source>
        <translation>由本視窗執行</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="907" />
        <source>run by %1</source>
        <translation>由 %1 執行</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="908" />
        <source>no runner: start tactus-cli serve or press Connect</source>
        <translation>沒有執行者：請啟動 tactus-cli serve 或按「連線」</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="913" />
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="916" />
        <source>Printer %1, %2</source>
        <translation>印表機 %1，%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="967" />
        <source>Job %1: %2 sent to the queue</source>
        <translation>工作 %1：%2 已送入佇列</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="992" />
        <source>%1: cancel sent to %2</source>
        <translation>%1：已向 %2 送出取消</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="993" />
        <source>Cancelling %1 on %2</source>
        <translation>正在取消 %2 上的 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="1011" />
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="1015" />
        <source>%1 is embossed again from sheet %2</source>
        <translation>%1 從第 %2 張重新列印</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="1021" />
        <source>Simulator: the paper runs out</source>
        <translation>模擬器：紙張用完</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="1025" />
        <source>Simulator: the cable is pulled for 5 seconds</source>
        <translation>模擬器：纜線拔除 5 秒</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="1029" />
        <source>Simulator: line noise for 2 seconds</source>
        <translation>模擬器：線路雜訊 2 秒</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="1033" />
        <source>Simulator: the controller resets</source>
        <translation>模擬器：控制器重設</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="474" />
        <source>Dis&amp;connect</source>
        <translation>中斷連線(&amp;C)</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="161" />
        <source>Embosser device</source>
        <translation>點字印表機裝置</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="522" />
        <source>Connected to %1</source>
        <translation>已連線到 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="517" />
        <source>Connected to %1: %2</source>
        <translation>已連線到 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="129" />
        <source>%1: %2</source>
        <comment>a message and its detail</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="64" />
        <source>Cannot list the CUPS queues on %1: %2</source>
        <translation>無法列出 CUPS 伺服器 %1 上的佇列：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="529" />
        <source>Disconnected from printer %1</source>
        <translation>已與印表機 %1 中斷連線</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="545" />
        <location filename="../../widgets/printer_panel.cpp" line="561" />
        <source>Cannot queue %1: %2</source>
        <translation>無法將 %1 排入佇列：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="565" />
        <source>Queued %1 as job %2 on printer %3</source>
        <translation>已將 %1 排入印表機 %3，工作 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel_queues.cpp" line="112" />
        <source>%1 at %2</source>
        <translation>%2 的 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="585" />
        <source>The print queue cannot be written (%1): this window stopped running printer %2</source>
        <translation>無法寫入列印佇列（%1）：本視窗已停止執行印表機 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="614" />
        <source>Cannot read the print queue: %1</source>
        <translation>無法讀取列印佇列：%1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="668" />
        <source>Embossing %1 (job %2) on %3</source>
        <translation>正在以 %3 列印 %1（工作 %2）</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="675" />
        <location filename="../../widgets/printer_panel.cpp" line="865" />
        <source>%1 paused: %2</source>
        <translation>%1 已暫停：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="682" />
        <source>%1 waits: %2</source>
        <translation>%1 等待中：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="719" />
        <source>%1 cancelled</source>
        <translation>%1 已取消</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="721" />
        <source>%1 stopped: %2. The job is kept; fix the problem, then resume it.</source>
        <translation>%1 已停止：%2。工作已保留；排除問題後請繼續。</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="783" />
        <source>Progress of %1</source>
        <translation>%1 的進度</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="566" />
        <source>%1 added to the queue</source>
        <translation>%1 已加入佇列</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="691" />
        <source>%1: sheet %2 of %3</source>
        <translation>%1：第 %2 張，共 %3 張</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="692" />
        <location filename="../../widgets/printer_panel.cpp" line="696" />
        <source>%1: %2 percent, sheet %3 of %4</source>
        <translation>%1：百分之 %2，第 %3 張，共 %4 張</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="669" />
        <source>Embossing %1</source>
        <translation>正在列印 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="711" />
        <location filename="../../widgets/printer_panel.cpp" line="741" />
        <source>Embossed %1</source>
        <translation>已列印 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="719" />
        <source>%1 cancelled; resume from sheet %2</source>
        <translation>%1 已取消；可從第 %2 張繼續</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="972" />
        <source>Pausing</source>
        <translation>正在暫停</translation>
    </message>
    <message>
        <location filename="../../widgets/printer_panel.cpp" line="982" />
        <source>Resuming</source>
        <translation>正在繼續</translation>
    </message>
</context>
<context>
    <name>tactus::gui::ProfileEditor</name>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="78" />
        <source>Paper</source>
        <translation>紙張</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="79" />
        <source>Width</source>
        <translation>寬度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="79" />
        <location filename="../../widgets/profile_editor.cpp" line="80" />
        <location filename="../../widgets/profile_editor.cpp" line="81" />
        <location filename="../../widgets/profile_editor.cpp" line="82" />
        <location filename="../../widgets/profile_editor.cpp" line="84" />
        <location filename="../../widgets/profile_editor.cpp" line="85" />
        <location filename="../../widgets/profile_editor.cpp" line="86" />
        <location filename="../../widgets/profile_editor.cpp" line="87" />
        <location filename="../../widgets/profile_editor.cpp" line="88" />
        <location filename="../../widgets/profile_editor.cpp" line="90" />
        <location filename="../../widgets/profile_editor.cpp" line="96" />
        <location filename="../../widgets/profile_editor.cpp" line="107" />
        <location filename="../../widgets/profile_editor.cpp" line="108" />
        <location filename="../../widgets/profile_editor.cpp" line="109" />
        <location filename="../../widgets/profile_editor.cpp" line="110" />
        <location filename="../../widgets/profile_editor.cpp" line="111" />
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="80" />
        <source>Height</source>
        <translation>高度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="81" />
        <source>Left margin</source>
        <translation>左邊界</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="82" />
        <source>Top margin</source>
        <translation>上邊界</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="83" />
        <source>Braille geometry</source>
        <translation>點字幾何</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="84" />
        <source>Dot pitch</source>
        <translation>點距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="85" />
        <source>Cell pitch</source>
        <translation>方距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="86" />
        <source>Line pitch</source>
        <translation>行距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="87" />
        <source>Back offset across</source>
        <translation>背面水平偏移</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="88" />
        <source>Back offset down</source>
        <translation>背面垂直偏移</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="89" />
        <source>Head and carriage</source>
        <translation>打點頭與字車</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="90" />
        <source>Concave hammer offset</source>
        <translation>凹錘偏移</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="91" />
        <source>Hammer dwell</source>
        <translation>擊錘停留</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="24" />
        <location filename="../../widgets/profile_editor.cpp" line="91" />
        <source>s</source>
        <translation>秒</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="25" />
        <source>steps/s</source>
        <translation>步/秒</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="32" />
        <source>%1 %2</source>
        <comment>a number and its unit</comment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="45" />
        <source>is %1, must be between %2 and %3</source>
        <translation>為 %1，必須介於 %2 與 %3 之間</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="46" />
        <source>is %1, must be above 0</source>
        <translation>為 %1，必須大於 0</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="47" />
        <source>is %1, must not exceed %2</source>
        <translation>為 %1，不可超過 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="48" />
        <source>is %1, below the physical minimum of %2</source>
        <translation>為 %1，低於物理下限 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="49" />
        <source>is %1, below %2: motion that slow would take days to plan and to emboss</source>
        <translation>為 %1，低於 %2：這麼慢的運動要花好幾天規劃與列印</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="51" />
        <source>needs %1, more than the controller can time (%2, 8 timer ticks per step)</source>
        <translation>需要 %1，超過控制器能計時的上限（%2，每步 8 個計時器刻度）</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="52" />
        <source>is %1, must exceed the dot pitch (%2) so neighbouring cells stay apart</source>
        <translation>為 %1，必須大於點距（%2），相鄰的點字方才不會相連</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="53" />
        <source>is %1, must exceed the cell height (%2)</source>
        <translation>為 %1，必須大於點字方的高度（%2）</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/profile_editor.cpp" line="55" />
        <source>%n cell(s) need %1 but the paper leaves %2 between the margins</source>
        <translation><numerusform>%n 方需要 %1，但紙張在邊界之間只有 %2</numerusform></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/profile_editor.cpp" line="57" />
        <source>%n line(s) need %1 but the paper leaves %2 between the margins</source>
        <translation><numerusform>%n 行需要 %1，但紙張在邊界之間只有 %2</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="58" />
        <source>is %1, which puts back-side dots off the paper</source>
        <translation>為 %1，背面的點會落在紙張之外</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="59" />
        <source>is %1, wider than the paper (%2): one hammer could never reach it</source>
        <translation>為 %1，比紙張（%2）還寬：有一支擊錘永遠打不到</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="61" />
        <source>is %1, finer than half a carriage step (%2): unreachable at any speed</source>
        <translation>為 %1，小於字車半步（%2）：任何速度都達不到</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="63" />
        <source>is %1</source>
        <translation>為 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="92" />
        <source>Carriage steps</source>
        <translation>字車步數</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="92" />
        <source>steps/mm</source>
        <translation>步/mm</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="93" />
        <source>Carriage top speed</source>
        <translation>字車最高速度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="93" />
        <source>mm/s</source>
        <translation>mm/s</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="94" />
        <source>Carriage acceleration</source>
        <translation>字車加速度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="94" />
        <source>mm/s²</source>
        <translation>mm/s²</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="95" />
        <source>Carriage jerk</source>
        <translation>字車加加速度</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="95" />
        <source>mm/s³</source>
        <translation>mm/s³</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="96" />
        <source>Carriage backlash</source>
        <translation>字車背隙</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="97" />
        <source>Step timing tolerance</source>
        <translation>步進時間容許誤差</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="97" />
        <source>of a step interval</source>
        <translation>個步進間隔</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="98" />
        <source>Dynamics and vibration</source>
        <translation>動態與振動</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="99" />
        <source>Head mass</source>
        <translation>打點頭質量</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="99" />
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="100" />
        <source>Belt stiffness</source>
        <translation>皮帶剛性</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="100" />
        <source>N/m</source>
        <translation>N/m</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="101" />
        <source>Damping ratio</source>
        <translation>阻尼比</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="102" />
        <source>Position tolerance at the strike</source>
        <translation>擊點時的位置容許誤差</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="102" />
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="106" />
        <source>Tactile graphics</source>
        <translation>觸覺圖形</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="107" />
        <source>Dot spacing along a solid line</source>
        <translation>實線的點距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="108" />
        <source>Dot spacing along a dotted line</source>
        <translation>點線的點距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="109" />
        <source>Gap between dashes</source>
        <translation>虛線段之間的間隔</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="110" />
        <source>Texture row spacing</source>
        <translation>紋理的行距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="111" />
        <source>Dot spacing along a texture row</source>
        <translation>紋理行上的點距</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="116" />
        <source>Profile fields</source>
        <translation>設定檔欄位</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="120" />
        <source>Profile check</source>
        <translation>設定檔檢查</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="121" />
        <source>&amp;Load profile...</source>
        <translation>載入設定檔(&amp;L)...</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="122" />
        <source>Save pr&amp;ofile...</source>
        <translation>儲存設定檔(&amp;O)...</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="123" />
        <source>&amp;Defaults</source>
        <translation>預設值(&amp;D)</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="125" />
        <source>Load printer profile</source>
        <translation>載入印表機設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="125" />
        <location filename="../../widgets/profile_editor.cpp" line="129" />
        <source>Profiles (*.json)</source>
        <translation>設定檔 (*.json)</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="129" />
        <source>Save printer profile</source>
        <translation>儲存印表機設定檔</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="152" />
        <source>%1 to %2 %3</source>
        <translation>%1 到 %2 %3</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="153" />
        <source>%1 in %2</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="154" />
        <source>Range %1; profile field %2</source>
        <translation>範圍 %1；設定檔欄位 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="157" />
        <source>%1:</source>
        <comment>a form field's label</comment>
        <translation>%1：</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="164" />
        <source>Invalid: %1. %2</source>
        <translation>無效：%1。%2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="199" />
        <source>%1 %2. The plan and preview keep the last valid profile.</source>
        <translation>%1 %2。規劃與預覽仍使用上一個有效的設定檔。</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="215" />
        <source>Profile is valid.</source>
        <translation>設定檔有效。</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="219" />
        <source>%1 is valid again.</source>
        <comment>a profile field whose error is fixed</comment>
        <translation>%1 又有效了。</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="227" />
        <source>Cannot load %1: %2</source>
        <translation>無法載入 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="233" />
        <source>Loaded profile %1</source>
        <translation>已載入設定檔 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="239" />
        <source>Cannot save %1: %2</source>
        <translation>無法儲存 %1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/profile_editor.cpp" line="242" />
        <source>Saved profile to %1</source>
        <translation>已將設定檔儲存到 %1</translation>
    </message>
</context>
<context>
    <name>tactus::gui::SheetPreview</name>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="127" />
        <source>Interpoint preview</source>
        <translation>雙面點字預覽</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="128" />
        <source>Arrow keys move between cells; Page Up and Page Down change sheet</source>
        <translation>方向鍵在點字方之間移動；Page Up 與 Page Down 換頁</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="242" />
        <source>Sheet %1 %2, line %3, cell %4</source>
        <translation>第 %1 張%2，第 %3 行，第 %4 方</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="244" />
        <location filename="../../widgets/sheet_preview.cpp" line="255" />
        <source>back</source>
        <translation>背面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="244" />
        <location filename="../../widgets/sheet_preview.cpp" line="255" />
        <source>front</source>
        <translation>正面</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="247" />
        <source>: no page</source>
        <translation>：沒有這一頁</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/sheet_preview.cpp" line="251" />
        <source>Graphic: %n dot(s).</source>
        <translation><numerusform>圖形：%n 點。</numerusform></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="253" />
        <source>Sheet %1 %2: %3</source>
        <comment>a sheet, its side, what its graphic is</comment>
        <translation>第 %1 張%2：%3</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="260" />
        <source>: blank</source>
        <translation>：空方</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="262" />
        <source>dots %1</source>
        <translation>點 %1</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="262" />
        <source>%1: %2</source>
        <comment>a cell's place and its dots</comment>
        <translation>%1：%2</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="267" />
        <location filename="../../widgets/sheet_preview.cpp" line="275" />
        <source>, in the word “%1”</source>
        <translation>，在「%1」中</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="281" />
        <location filename="../../widgets/sheet_preview.cpp" line="369" />
        <source>No document</source>
        <translation>沒有文件</translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="282" />
        <source>Sheet %1 of %2</source>
        <translation>第 %1 張，共 %2 張</translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/sheet_preview.cpp" line="284" />
        <source>; %n front and back dots too close</source>
        <translation><numerusform>；有 %n 組正背面點距離過近</numerusform></translation>
    </message>
</context>
<context>
    <name>tactus::gui::TablePicker</name>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="16" />
        <source>Unified English Braille</source>
        <translation>統一英文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="17" />
        <source>English Braille American Edition</source>
        <translation>美國版英文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="18" />
        <source>Taiwanese braille (bopomofo)</source>
        <translation>台灣國語點字（注音）</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="19" />
        <source>current Chinese braille</source>
        <translation>現行中文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="20" />
        <source>two-cell Chinese braille</source>
        <translation>雙拼中文點字</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="21" />
        <source>uncontracted</source>
        <translation>未縮寫</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="22" />
        <source>partly contracted</source>
        <translation>部分縮寫</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="23" />
        <source>contracted</source>
        <translation>縮寫</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="24" />
        <source>grade %1</source>
        <translation>第 %1 級</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="26" />
        <source>, </source>
        <comment>list separator</comment>
        <translation>，</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="33" />
        <source>Braille table</source>
        <translation>點字表</translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="34" />
        <source>The language and braille code the print is translated with</source>
        <translation>用來轉譯明眼字的語言與點字系統</translation>
    </message>
</context>
<context>
    <name>tactus::gui::VibrationView</name>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="28" />
        <source>Step response against the targets</source>
        <translation>步階響應與目標比較</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="29" />
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="29" />
        <source>Value</source>
        <translation>數值</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="29" />
        <source>Target</source>
        <translation>目標</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="29" />
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="35" />
        <source>Natural frequencies</source>
        <translation>自然頻率</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="39" />
        <source>Residual vibration at the strikes</source>
        <translation>擊點時的殘留振動</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="43" />
        <source>Residual vibration histogram</source>
        <translation>殘留振動直方圖</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="48" />
        <source>Frequency response chart</source>
        <translation>頻率響應圖</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="77" />
        <source>pass</source>
        <translation>通過</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="77" />
        <source>FAIL</source>
        <translation>未通過</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="81" />
        <source>Overshoot</source>
        <translation>超越量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="81" />
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="81" />
        <source>&lt; %1 %</source>
        <translation>&lt; %1 %</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="83" />
        <source>Rise time (10-90 %)</source>
        <translation>上升時間（10-90 %）</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="83" />
        <location filename="../../widgets/vibration_view.cpp" line="86" />
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="84" />
        <location filename="../../widgets/vibration_view.cpp" line="87" />
        <source>&lt; %1 ms</source>
        <translation>&lt; %1 ms</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="85" />
        <source>Settling time (2 %)</source>
        <translation>安定時間（2 %）</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="86" />
        <source>never settles</source>
        <translation>無法安定</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="95" />
        <source>%1 model; natural frequencies %2 Hz; √(k/m) = %3 rad/s; damping ratio %4.</source>
        <translation>%1模型；自然頻率 %2 Hz；√(k/m) = %3 rad/s；阻尼比 %4。</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="96" />
        <source>Two-inertia</source>
        <translation>雙慣量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="96" />
        <source>One-inertia</source>
        <translation>單慣量</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="104" />
        <source>Magnitude (dB)</source>
        <translation>增益 (dB)</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="106" />
        <source>Phase (degrees)</source>
        <translation>相位（度）</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="121" />
        <source>Frequency (Hz)</source>
        <translation>頻率 (Hz)</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="124" />
        <source>dB</source>
        <translation>dB</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="126" />
        <source>degrees</source>
        <translation>度</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="134" />
        <source>Head position versus command</source>
        <translation>打點頭位置對命令</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="135" />
        <source>Peak %1 dB at %2 Hz; %3 points from %4 to %5 Hz.</source>
        <translation>峰值 %1 dB 於 %2 Hz；%3 個點，從 %4 到 %5 Hz。</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="141" />
        <source>All targets met</source>
        <translation>全部達到目標</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="141" />
        <source>Some targets are not met</source>
        <translation>部分未達目標</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="151" />
        <source>No plan yet</source>
        <translation>尚未規劃</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="164" />
        <source>sheet %1, pass %2</source>
        <translation>第 %1 張行程 %2</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="170" />
        <source>Nominal machine</source>
        <translation>標稱機器</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="171" />
        <source>Worst case over the band</source>
        <translation>參數範圍內最差情況</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="190" />
        <source>Residual up to (µm)</source>
        <translation>殘留振動上限 (µm)</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="192" />
        <source>Strikes</source>
        <translation>擊點</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="199" />
        <source>Residual vibration per strike</source>
        <translation>每個擊點的殘留振動</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="201" />
        <source>%1 strikes on %2 planned sheets: worst case %3 µm at %4 (tolerance %5 µm) — %6.</source>
        <translation>已規劃 %2 張共 %1 個擊點：最差 %3 µm，位於%4（容許 %5 µm）— %6。</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="207" />
        <source>within tolerance</source>
        <translation>在容許範圍內</translation>
    </message>
    <message>
        <location filename="../../widgets/vibration_view.cpp" line="207" />
        <source>OVER TOLERANCE</source>
        <translation>超出容許範圍</translation>
    </message>
</context>
<context>
    <name>tactus::gui::structured</name>
    <message>
        <location filename="../../widgets/structured_print.cpp" line="157" />
        <source>Picture</source>
        <translation>圖片</translation>
    </message>
</context>
</TS>