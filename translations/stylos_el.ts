<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="el">
    <context>
        <name>stylos::app::CommandLine</name>
        <message>
            <source>Stylos, a workbench for very large 3D scans of monuments. With no file, opens the demo scene.</source>
            <translation>Stylos, ένα εργαλείο για πολύ μεγάλες τρισδιάστατες σαρώσεις μνημείων. Χωρίς αρχείο, ανοίγει τη σκηνή επίδειξης.</translation>
        </message>
        <message>
            <source>Wait until loading ends, save the window as a PNG image to &lt;file&gt; and exit (status 1 if a file could not be loaded).</source>
            <translation>Αναμονή έως το τέλος της φόρτωσης, αποθήκευση του παραθύρου ως εικόνας PNG στο &lt;αρχείο&gt; και έξοδος (κωδικός 1 αν κάποιο αρχείο δεν φορτώθηκε).</translation>
        </message>
        <message>
            <source>file</source>
            <translation>αρχείο</translation>
        </message>
        <message>
            <source>Point files to load (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ).</source>
            <translation>Αρχεία σημείων προς φόρτωση (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ).</translation>
        </message>
    </context>
    <context>
        <name>stylos::app::MainActions</name>
        <message>
            <source>&amp;File</source>
            <translation>&amp;Αρχείο</translation>
        </message>
        <message>
            <source>&amp;Help</source>
            <translation>&amp;Βοήθεια</translation>
        </message>
        <message>
            <source>&amp;Open scans…</source>
            <translation>Ά&amp;νοιγμα σαρώσεων…</translation>
        </message>
        <message>
            <source>Load point files (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ) into the scene</source>
            <translation>Φόρτωση αρχείων σημείων (PLY, LAS, XYZ, ASC, CSV, PTS, TXT, OBJ) στη σκηνή</translation>
        </message>
        <message>
            <source>&amp;Quit</source>
            <translation>Έ&amp;ξοδος</translation>
        </message>
        <message>
            <source>Open &amp;demo</source>
            <translation>Άνοιγμα &amp;επίδειξης</translation>
        </message>
        <message>
            <source>Replace the scene by the demo scene: a fluted drum, two fragments and an omphalos</source>
            <translation>Αντικατάσταση της σκηνής από τη σκηνή επίδειξης: ένας ραβδωτός σπόνδυλος, δύο θραύσματα και ένας ομφαλός</translation>
        </message>
        <message>
            <source>&amp;About Stylos</source>
            <translation>&amp;Σχετικά με το Stylos</translation>
        </message>
        <message>
            <source>Point files (*.ply *.las *.xyz *.asc *.csv *.pts *.txt *.obj)</source>
            <translation>Αρχεία σημείων (*.ply *.las *.xyz *.asc *.csv *.pts *.txt *.obj)</translation>
        </message>
        <message>
            <source>All files (*)</source>
            <translation>Όλα τα αρχεία (*)</translation>
        </message>
        <message>
            <source>Open scans</source>
            <translation>Άνοιγμα σαρώσεων</translation>
        </message>
        <message>
            <source>About Stylos</source>
            <translation>Σχετικά με το Stylos</translation>
        </message>
        <message>
            <source>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;A workbench for very large 3D scans of monuments: column drums, capitals, fragments.&lt;/p&gt;&lt;p&gt;Point-based, after Duguet, Drettakis, Girardeau-Montaut, Martinez and Schneider (VAST 2004).&lt;/p&gt;</source>
            <translation>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;Ένα εργαλείο για πολύ μεγάλες τρισδιάστατες σαρώσεις μνημείων: σπόνδυλοι κιόνων, κιονόκρανα, θραύσματα.&lt;/p&gt;&lt;p&gt;Βασισμένο σε σημεία, κατά τους Duguet, Drettakis, Girardeau-Montaut, Martinez και Schneider (VAST 2004).&lt;/p&gt;</translation>
        </message>
    </context>
    <context>
        <name>stylos::app::MainWindow</name>
        <message>
            <source>Stylos</source>
            <translation>Stylos</translation>
        </message>
        <message>
            <source>Cancelled</source>
            <translation>Ακυρώθηκε</translation>
        </message>
        <message numerus="yes">
            <source>%n file(s) in the scene</source>
            <translation>
                <numerusform>%n αρχείο στη σκηνή</numerusform>
                <numerusform>%n αρχεία στη σκηνή</numerusform>
            </translation>
        </message>
        <message numerus="yes">
            <source>%n problem(s) while loading:</source>
            <translation>
                <numerusform>%n πρόβλημα κατά τη φόρτωση:</numerusform>
                <numerusform>%n προβλήματα κατά τη φόρτωση:</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::DemoScene</name>
        <message>
            <source>Could not create the demo folder %1.</source>
            <translation>Δεν ήταν δυνατή η δημιουργία του φακέλου επίδειξης %1.</translation>
        </message>
        <message>
            <source>Generating the demo scene</source>
            <translation>Δημιουργία της σκηνής επίδειξης</translation>
        </message>
        <message>
            <source>Could not generate the demo scene: %1.</source>
            <translation>Δεν ήταν δυνατή η δημιουργία της σκηνής επίδειξης: %1.</translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::ErrorText</name>
        <message>
            <source>Could not load %1: %2.</source>
            <translation>Δεν ήταν δυνατή η φόρτωση του %1: %2.</translation>
        </message>
        <message>
            <source>the file does not exist</source>
            <translation>το αρχείο δεν υπάρχει</translation>
        </message>
        <message>
            <source>the file cannot be read</source>
            <translation>το αρχείο δεν μπορεί να διαβαστεί</translation>
        </message>
        <message>
            <source>the file format is not recognised</source>
            <translation>η μορφή του αρχείου δεν αναγνωρίζεται</translation>
        </message>
        <message>
            <source>this format is not supported</source>
            <translation>αυτή η μορφή δεν υποστηρίζεται</translation>
        </message>
        <message>
            <source>the file is malformed</source>
            <translation>το αρχείο είναι κακοσχηματισμένο</translation>
        </message>
        <message>
            <source>the file is truncated</source>
            <translation>το αρχείο είναι περικομμένο</translation>
        </message>
        <message>
            <source>the file is empty</source>
            <translation>το αρχείο είναι κενό</translation>
        </message>
        <message>
            <source>the output could not be written</source>
            <translation>η έξοδος δεν μπόρεσε να γραφτεί</translation>
        </message>
        <message>
            <source>a parameter is out of range</source>
            <translation>μια παράμετρος είναι εκτός ορίων</translation>
        </message>
        <message>
            <source>not enough memory for this operation</source>
            <translation>ανεπαρκής μνήμη για αυτή τη λειτουργία</translation>
        </message>
        <message>
            <source>cancelled</source>
            <translation>ακυρώθηκε</translation>
        </message>
        <message>
            <source>unknown error</source>
            <translation>άγνωστο σφάλμα</translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneLoader</name>
        <message numerus="yes">
            <source>Loading %n file(s)</source>
            <translation>
                <numerusform>Φόρτωση %n αρχείου</numerusform>
                <numerusform>Φόρτωση %n αρχείων</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneSummaryModel</name>
        <message>
            <source>min (%1, %2, %3)
max (%4, %5, %6)</source>
            <translation>ελάχ. (%1, %2, %3)
μέγ. (%4, %5, %6)</translation>
        </message>
        <message>
            <source>none</source>
            <translation>κανένα</translation>
        </message>
        <message>
            <source>File</source>
            <translation>Αρχείο</translation>
        </message>
        <message>
            <source>Format</source>
            <translation>Μορφή</translation>
        </message>
        <message>
            <source>Points</source>
            <translation>Σημεία</translation>
        </message>
        <message>
            <source>Skipped</source>
            <translation>Παραλείφθηκαν</translation>
        </message>
        <message>
            <source>Size (x × y × z)</source>
            <translation>Διαστάσεις (x × y × z)</translation>
        </message>
        <message>
            <source>Attributes</source>
            <translation>Ιδιότητες</translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::SceneSummaryWidget</name>
        <message>
            <source>No scan loaded</source>
            <translation>Δεν έχει φορτωθεί σάρωση</translation>
        </message>
        <message numerus="yes">
            <source>Total: %1 points in %n file(s)</source>
            <translation>
                <numerusform>Σύνολο: %1 σημεία σε %n αρχείο</numerusform>
                <numerusform>Σύνολο: %1 σημεία σε %n αρχεία</numerusform>
            </translation>
        </message>
    </context>
    <context>
        <name>stylos::widgets::TaskStatusWidget</name>
        <message>
            <source>Cancel</source>
            <translation>Ακύρωση</translation>
        </message>
        <message>
            <source>Stop the running task</source>
            <translation>Διακοπή της τρέχουσας εργασίας</translation>
        </message>
    </context>
</TS>
