<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_TW">
<context>
    <name>QObject</name>
    <message>
        <location filename="../../widgets/editor_widget.cpp" line="18"/>
        <source>typing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="55"/>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="59"/>
        <source>Saving %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="49"/>
        <source>front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="50"/>
        <source>back, as read after turning the sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="51"/>
        <source>front and back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="53"/>
        <source>Sheet %1 (%2) - pages %3 / %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="387"/>
        <source>Tactus interpoint proof</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="394"/>
        <source>Cannot write %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="405"/>
        <source>Cannot finish %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../../app/gui/main.cpp" line="30"/>
        <source>Braille editor and embosser print manager: edit print and braille side by side, preview interpoint sheets, emboss.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="36"/>
        <source>Document to open (Markdown, text, DOCX, BRF, PEF).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="39"/>
        <source>liblouis table, e.g. en-ueb-g2.ctb or zh-tw.ctb.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="42"/>
        <source>Preview side: front, back or both.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="44"/>
        <source>Sheet to preview.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="47"/>
        <source>User interface language, e.g. zh_TW.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="50"/>
        <source>Save a picture of the window and quit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/gui/main.cpp" line="53"/>
        <source>Do not offer to recover autosaved work.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactus::gui::BraillePane</name>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="37"/>
        <source>Braille</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="39"/>
        <source>The braille of each paragraph. Type with S D F J K L as dots 3 2 1 4 5 6; space, backspace and delete edit cells</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactus::gui::FindReplaceDialog</name>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="21"/>
        <source>Find and Replace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="24"/>
        <source>Find</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="26"/>
        <source>Replace with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="27"/>
        <source>&amp;Match case</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="28"/>
        <source>&amp;Whole words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="30"/>
        <source>Search result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="32"/>
        <source>F&amp;ind:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="33"/>
        <source>Re&amp;place with:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="37"/>
        <source>Find &amp;Next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="38"/>
        <source>Find Pre&amp;vious</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="39"/>
        <source>&amp;Replace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="40"/>
        <source>Replace &amp;All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="74"/>
        <source>“%1” not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/find_replace.cpp" line="79"/>
        <source>Found on line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/find_replace.cpp" line="114"/>
        <source>%n replaced</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::MainWindow</name>
    <message>
        <location filename="../../widgets/main_window.cpp" line="71"/>
        <location filename="../../widgets/main_window.cpp" line="382"/>
        <location filename="../../widgets/main_window.cpp" line="502"/>
        <source>Tactus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="81"/>
        <location filename="../../widgets/main_window.cpp" line="83"/>
        <source>Preview</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="89"/>
        <source>Braille</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="91"/>
        <source>Braille toolbar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="92"/>
        <source>&amp;Table:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="99"/>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="101"/>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="155"/>
        <source>&amp;New</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="158"/>
        <source>&amp;Open or Import...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="159"/>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="160"/>
        <source>Save &amp;As...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="161"/>
        <source>Export &amp;BRF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="161"/>
        <source>Ctrl+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="163"/>
        <source>Export &amp;PEF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="163"/>
        <source>Ctrl+Shift+E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="165"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="166"/>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="169"/>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="173"/>
        <source>&amp;Find and Replace...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="179"/>
        <source>Find &amp;Next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="181"/>
        <source>Go to &amp;print text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="181"/>
        <source>Ctrl+1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="183"/>
        <source>Go to &amp;braille</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="183"/>
        <source>Ctrl+2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="185"/>
        <source>Go to pre&amp;view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="185"/>
        <source>Ctrl+3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="187"/>
        <source>Choose braille &amp;table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="187"/>
        <source>Ctrl+T</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="191"/>
        <source>&amp;Keyboard Shortcuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="191"/>
        <source>Ctrl+F1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="193"/>
        <source>&amp;About Tactus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="193"/>
        <source>Shift+F1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="198"/>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="200"/>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="206"/>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="211"/>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="216"/>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="243"/>
        <source>Translating with %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="248"/>
        <source>Cannot use table %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="251"/>
        <location filename="../../widgets/main_window.cpp" line="346"/>
        <source>Braille table: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="266"/>
        <source>Open or import</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="267"/>
        <source>Documents (*.md *.markdown *.txt *.docx *.brf *.pef);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="273"/>
        <source>Opening %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="287"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="295"/>
        <source>%1 percent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="316"/>
        <source>Cancelled; the document is unchanged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="321"/>
        <source>Cannot open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="322"/>
        <source>the document</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="338"/>
        <source>Opened %1: %n sheet(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="340"/>
        <source>%n line(s) could not be translated; they are left out of the braille</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="359"/>
        <source>Sheet %1 of %2%3 | line %4 | cell %5 | print page %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="362"/>
        <source>, back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="362"/>
        <source>, front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="374"/>
        <location filename="../../widgets/main_window.cpp" line="503"/>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="391"/>
        <source>Save as Markdown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="391"/>
        <source>Markdown (*.md)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="413"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="418"/>
        <location filename="../../widgets/main_window.cpp" line="455"/>
        <source>untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="419"/>
        <source>PEF (*.pef)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="419"/>
        <source>Braille ASCII (*.brf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="420"/>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="441"/>
        <source>Cannot export %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/main_window.cpp" line="450"/>
        <source>Exported %1 (%n sheet(s))</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="456"/>
        <source>Print preview to PDF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="457"/>
        <source>PDF (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="468"/>
        <source>Wrote proof %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="502"/>
        <source>Save the changes to %1?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="582"/>
        <source>Cannot read the autosaved copy %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="597"/>
        <source>Recovered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="603"/>
        <source>Recovered unsaved changes to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="609"/>
        <source>an untitled document</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="611"/>
        <source>Recover unsaved work</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="612"/>
        <source>Tactus closed without saving %1 (autosaved %2). Recover it?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="630"/>
        <source>Keyboard Shortcuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="634"/>
        <source>Shortcuts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="636"/>
        <source>Action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="636"/>
        <source>Shortcut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="664"/>
        <source>Braille pane: dots 1 2 3 4 5 6 (chord, released together)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="664"/>
        <source>F D S J K L</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="665"/>
        <source>Braille pane: blank cell / erase cell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="665"/>
        <source>Space / Backspace, Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="666"/>
        <source>Preview: move between cells / lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="666"/>
        <source>Arrow keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="667"/>
        <source>Preview: turn to the other side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="667"/>
        <source>Space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="668"/>
        <source>Preview: previous / next sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="668"/>
        <source>PgUp / PgDown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="669"/>
        <source>Move between panes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="669"/>
        <source>Tab / Shift+Tab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="674"/>
        <source>About Tactus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/main_window.cpp" line="675"/>
        <source>&lt;p&gt;&lt;b&gt;Tactus %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Braille editor and embosser print manager.&lt;/p&gt;&lt;p&gt;Licensed under the GNU GPL, version 3 or later.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactus::gui::PreviewPanel</name>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="18"/>
        <source>Preview scroll area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="34"/>
        <source>&amp;Front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="34"/>
        <source>Ctrl+Alt+F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="35"/>
        <source>&amp;Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="35"/>
        <source>Ctrl+Alt+B</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="36"/>
        <source>Front &amp;and back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="36"/>
        <source>Ctrl+Alt+A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="42"/>
        <source>&amp;Previous sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="42"/>
        <source>Ctrl+PgUp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="43"/>
        <source>&amp;Next sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="43"/>
        <source>Ctrl+PgDown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="44"/>
        <source>Zoom &amp;in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="45"/>
        <source>Zoom &amp;out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="46"/>
        <source>&amp;High contrast</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="46"/>
        <source>Ctrl+Alt+H</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="48"/>
        <source>Print preview to P&amp;DF...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="48"/>
        <source>Ctrl+Alt+P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="60"/>
        <source>Preview</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="62"/>
        <source>Preview controls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/preview_panel.cpp" line="68"/>
        <source>Preview status</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactus::gui::PrintPane</name>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="123"/>
        <source>Print text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/braille_pane.cpp" line="125"/>
        <source>One paragraph per line: # for headings, - for list items, *italic*, **bold**</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tactus::gui::SheetPreview</name>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="106"/>
        <source>Interpoint preview</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="107"/>
        <source>Arrow keys move between cells; Page Up and Page Down change sheet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="206"/>
        <source>Sheet %1 %2, line %3, cell %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="208"/>
        <source>back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="208"/>
        <source>front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="211"/>
        <source>: no page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="215"/>
        <source>: blank</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="217"/>
        <source>dots %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="224"/>
        <source>, in the word “%1”</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="230"/>
        <location filename="../../widgets/sheet_preview.cpp" line="313"/>
        <source>No document</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/sheet_preview.cpp" line="231"/>
        <source>Sheet %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../widgets/sheet_preview.cpp" line="233"/>
        <source>; %n front and back dots too close</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tactus::gui::TablePicker</name>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="10"/>
        <source>Braille table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/table_picker.cpp" line="11"/>
        <source>The language and braille code the print is translated with</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
