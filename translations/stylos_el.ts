<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="el">
<context>
    <name>QAbstractFileIconProvider</name>
    <message>
        <source>Drive</source>
        <translation>Μονάδα δίσκου</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Άγνωστο</translation>
    </message>
    <message>
        <source>Folder</source>
        <comment>All other platforms</comment>
        <translation>Φάκελος</translation>
    </message>
    <message>
        <source>Shortcut</source>
        <comment>All other platforms</comment>
        <translation>Συντόμευση</translation>
    </message>
</context>
<context>
    <name>QFileDialog</name>
    <message>
        <source>Look in:</source>
        <translation>Αναζήτηση σε:</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Πίσω</translation>
    </message>
    <message>
        <source>Go back</source>
        <translation>Μετάβαση πίσω</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>Εμπρός</translation>
    </message>
    <message>
        <source>Go forward</source>
        <translation>Μετάβαση εμπρός</translation>
    </message>
    <message>
        <source>Parent Directory</source>
        <translation>Γονικός φάκελος</translation>
    </message>
    <message>
        <source>Go to the parent directory</source>
        <translation>Μετάβαση στον γονικό φάκελο</translation>
    </message>
    <message>
        <source>Create New Folder</source>
        <translation>Δημιουργία νέου φακέλου</translation>
    </message>
    <message>
        <source>Create a New Folder</source>
        <translation>Δημιουργία νέου φακέλου</translation>
    </message>
    <message>
        <source>List View</source>
        <translation>Προβολή λίστας</translation>
    </message>
    <message>
        <source>Change to list view mode</source>
        <translation>Αλλαγή σε προβολή λίστας</translation>
    </message>
    <message>
        <source>Detail View</source>
        <translation>Προβολή λεπτομερειών</translation>
    </message>
    <message>
        <source>Change to detail view mode</source>
        <translation>Αλλαγή σε προβολή λεπτομερειών</translation>
    </message>
    <message>
        <source>Sidebar</source>
        <translation>Πλευρική στήλη</translation>
    </message>
    <message>
        <source>List of places and bookmarks</source>
        <translation>Λίστα τοποθεσιών και σελιδοδεικτών</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Αρχεία</translation>
    </message>
    <message>
        <source>File &amp;name:</source>
        <translation>Όνομα &amp;αρχείου:</translation>
    </message>
    <message>
        <source>Files of type:</source>
        <translation>Αρχεία τύπου:</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>Ά&amp;νοιγμα</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Αποθήκευση</translation>
    </message>
    <message>
        <source>&amp;Choose</source>
        <translation>&amp;Επιλογή</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Άνοιγμα</translation>
    </message>
    <message>
        <source>Save As</source>
        <translation>Αποθήκευση ως</translation>
    </message>
    <message>
        <source>All Files (*)</source>
        <translation>Όλα τα αρχεία (*)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Όλα τα αρχεία (*)</translation>
    </message>
    <message>
        <source>Directory:</source>
        <translation>Φάκελος:</translation>
    </message>
    <message>
        <source>Directories</source>
        <translation>Φάκελοι</translation>
    </message>
    <message>
        <source>Find Directory</source>
        <translation>Εύρεση φακέλου</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Αρχείο</translation>
    </message>
    <message>
        <source>File Folder</source>
        <translation>Φάκελος αρχείων</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Φάκελος</translation>
    </message>
    <message>
        <source>%1 File</source>
        <translation>Αρχείο %1</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>Άγνωστο</translation>
    </message>
    <message>
        <source>New Folder</source>
        <translation>Νέος φάκελος</translation>
    </message>
    <message>
        <source>&amp;New Folder</source>
        <translation>&amp;Νέος φάκελος</translation>
    </message>
    <message>
        <source>&amp;Rename</source>
        <translation>&amp;Μετονομασία</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Διαγραφή</translation>
    </message>
    <message>
        <source>Show &amp;hidden files</source>
        <translation>Εμφάνιση &amp;κρυφών αρχείων</translation>
    </message>
    <message>
        <source>Recent Places</source>
        <translation>Πρόσφατες τοποθεσίες</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Ο υπολογιστής μου</translation>
    </message>
    <message>
        <source>%1 already exists.
Do you want to replace it?</source>
        <translation>Το %1 υπάρχει ήδη.
Θέλετε να αντικατασταθεί;</translation>
    </message>
    <message>
        <source>%1
File not found.
Please verify the correct file name was given.</source>
        <translation>%1
Το αρχείο δεν βρέθηκε.
Ελέγξτε ότι δόθηκε το σωστό όνομα αρχείου.</translation>
    </message>
    <message>
        <source>%1
Directory not found.
Please verify the correct directory name was given.</source>
        <translation>%1
Ο φάκελος δεν βρέθηκε.
Ελέγξτε ότι δόθηκε το σωστό όνομα φακέλου.</translation>
    </message>
    <message>
        <source>Are you sure you want to delete &apos;%1&apos;?</source>
        <translation>Θέλετε σίγουρα να διαγράψετε το «%1»;</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is write protected.
Do you want to delete it anyway?</source>
        <translation>Το «%1» προστατεύεται από εγγραφή.
Θέλετε να διαγραφεί παρ’ όλα αυτά;</translation>
    </message>
    <message>
        <source>Could not delete directory.</source>
        <translation>Δεν ήταν δυνατή η διαγραφή του φακέλου.</translation>
    </message>
</context>
<context>
    <name>QFileSystemModel</name>
    <message>
        <source>Name</source>
        <translation>Όνομα</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Μέγεθος</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>Τύπος</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Είδος</translation>
    </message>
    <message>
        <source>Date Modified</source>
        <translation>Ημερομηνία τροποποίησης</translation>
    </message>
    <message>
        <source>Computer</source>
        <translation>Υπολογιστής</translation>
    </message>
    <message>
        <source>My Computer</source>
        <translation>Ο υπολογιστής μου</translation>
    </message>
    <message>
        <source>Invalid filename</source>
        <translation>Μη έγκυρο όνομα αρχείου</translation>
    </message>
</context>
<context>
    <name>QPlatformTheme</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Αποθήκευση</translation>
    </message>
    <message>
        <source>Save All</source>
        <translation>Αποθήκευση όλων</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Άνοιγμα</translation>
    </message>
    <message>
        <source>&amp;Yes</source>
        <translation>&amp;Ναι</translation>
    </message>
    <message>
        <source>Yes to &amp;All</source>
        <translation>Ναι σε ό&amp;λα</translation>
    </message>
    <message>
        <source>&amp;No</source>
        <translation>Ό&amp;χι</translation>
    </message>
    <message>
        <source>N&amp;o to All</source>
        <translation>Όχι σε όλ&amp;α</translation>
    </message>
    <message>
        <source>Abort</source>
        <translation>Διακοπή</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Νέα προσπάθεια</translation>
    </message>
    <message>
        <source>Ignore</source>
        <translation>Παράβλεψη</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Κλείσιμο</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Ακύρωση</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Απόρριψη</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Βοήθεια</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Εφαρμογή</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Επαναφορά</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Προεπιλογές</translation>
    </message>
</context>
<context>
    <name>stylos::app::AnnotationActions</name>
    <message>
        <source>The legend has no class in this layer: add one first</source>
        <translation>Το υπόμνημα δεν έχει καμία κατηγορία σε αυτό το επίπεδο: προσθέστε πρώτα μία</translation>
    </message>
    <message>
        <source>Erase with the lasso</source>
        <translation>Σβήσιμο με το λάσο</translation>
    </message>
    <message>
        <source>Lasso in 3D</source>
        <translation>Λάσο σε 3Δ</translation>
    </message>
    <message>
        <source>Lasso: no fragment selected or under the lasso</source>
        <translation>Λάσο: κανένα θραύσμα επιλεγμένο ή κάτω από το λάσο</translation>
    </message>
    <message>
        <source>Lasso: no visible cell changed</source>
        <translation>Λάσο: καμία ορατή κυψέλη δεν άλλαξε</translation>
    </message>
    <message>
        <source>Annotate in 3D (&amp;lasso)</source>
        <translation>Σχολιασμός σε 3Δ (&amp;λάσο)</translation>
    </message>
    <message>
        <source>Draw a lasso in the 3D view: the visible cells of the selected fragment inside it take the chosen class; Ctrl erases; Escape cancels; Alt-drag orbits</source>
        <translation>Σχεδιάστε ένα λάσο στην 3Δ προβολή: οι ορατές κυψέλες του επιλεγμένου θραύσματος μέσα του παίρνουν την επιλεγμένη κατηγορία· Ctrl σβήνει· Escape ακυρώνει· Alt-σύρσιμο περιστρέφει</translation>
    </message>
    <message>
        <source>&amp;Erase with the lasso</source>
        <translation>&amp;Σβήσιμο με το λάσο</translation>
    </message>
    <message>
        <source>The lasso removes the class of the cells it takes</source>
        <translation>Το λάσο αφαιρεί την κατηγορία των κυψελών που παίρνει</translation>
    </message>
    <message>
        <source>The class the lasso gives</source>
        <translation>Η κατηγορία που δίνει το λάσο</translation>
    </message>
    <message>
        <source>&amp;Material / condition layer</source>
        <translation>Επίπεδο &amp;υλικού / κατάστασης</translation>
    </message>
    <message>
        <source>&amp;Tool mark layer</source>
        <translation>Επίπεδο ί&amp;χνών εργαλείου</translation>
    </message>
    <message>
        <source>3D lasso</source>
        <comment>toolbar</comment>
        <translation>Λάσο 3D</translation>
    </message>
    <message>
        <source>Erase</source>
        <comment>toolbar</comment>
        <translation>Σβήσιμο</translation>
    </message>
    <message>
        <source>Lasso: the selected fragment is hidden; show it to annotate it in 3D</source>
        <translation>Λάσο: το επιλεγμένο θραύσμα είναι κρυμμένο· εμφανίστε το για να το σχολιάσετε σε 3Δ</translation>
    </message>
</context>
<context>
    <name>stylos::app::AssemblyActions</name>
    <message>
        <source>Assembly %1</source>
        <translation>Συναρμολόγηση %1</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n fragment(s)</source>
        <translation>
            <numerusform>%1: %n θραύσμα</numerusform>
            <numerusform>%1: %n θραύσματα</numerusform>
        </translation>
    </message>
    <message>
        <source>New &amp;assembly from selection</source>
        <translation>Νέα &amp;συναρμολόγηση από την επιλογή</translation>
    </message>
    <message>
        <source>Group the selected fragments into an assembly that moves as one; a drum among them (a fragment with an axis guide) becomes what they dock against</source>
        <translation>Ομαδοποίηση των επιλεγμένων θραυσμάτων σε συναρμολόγηση που κινείται ενιαία· ένας σπόνδυλος ανάμεσά τους (θραύσμα με οδηγό άξονα) γίνεται αυτός στον οποίο προσαρμόζονται</translation>
    </message>
    <message>
        <source>&amp;Take out of assembly</source>
        <translation>&amp;Αφαίρεση από τη συναρμολόγηση</translation>
    </message>
    <message>
        <source>Move the selected fragments back to the top of the scene, where they are</source>
        <translation>Επιστροφή των επιλεγμένων θραυσμάτων στο πρώτο επίπεδο της σκηνής, εκεί όπου βρίσκονται</translation>
    </message>
    <message>
        <source>&amp;Remove assembly</source>
        <translation>&amp;Διάλυση συναρμολόγησης</translation>
    </message>
    <message>
        <source>Dissolve the selected assembly; its fragments stay where they are</source>
        <translation>Διάλυση της επιλεγμένης συναρμολόγησης· τα θραύσματά της μένουν όπου βρίσκονται</translation>
    </message>
    <message>
        <source>&amp;Use as the assembly&apos;s drum</source>
        <translation>&amp;Χρήση ως σπονδύλου της συναρμολόγησης</translation>
    </message>
    <message>
        <source>Dock the assembly&apos;s fragments against the guides of the selected fragment</source>
        <translation>Προσαρμογή των θραυσμάτων της συναρμολόγησης στους οδηγούς του επιλεγμένου θραύσματος</translation>
    </message>
    <message>
        <source>Dé&amp;veloppée of the assembly</source>
        <translation>Ανά&amp;πτυγμα της συναρμολόγησης</translation>
    </message>
    <message>
        <source>Unroll the assembly&apos;s drum with every fragment of the assembly at its place, on the drum&apos;s axis: the reconstruction in 2D, the free places; click a fragment to select it</source>
        <translation>Ξετύλιγμα του σπονδύλου της συναρμολόγησης με κάθε θραύσμα της στη θέση του, στον άξονα του σπονδύλου: η αναστήλωση σε 2D, οι ελεύθερες θέσεις· κλικ σε ένα θραύσμα το επιλέγει</translation>
    </message>
</context>
<context>
    <name>stylos::app::Automation</name>
    <message>
        <source>Demo drum (%1): A, développée under the skydome, material and condition in colour; B, front view lit from the viewer, the same classes as black-and-white hatches. Generated scan; the painted regions are an illustration.</source>
        <translation>Σπόνδυλος επίδειξης (%1): A, ανάπτυγμα υπό θόλο ουρανού, υλικό και κατάσταση σε χρώμα· B, πρόσοψη φωτισμένη από τον παρατηρητή, οι ίδιες κλάσεις ως ασπρόμαυρες διαγραμμίσεις. Παραγόμενη σάρωση· οι βαμμένες περιοχές είναι ενδεικτικές.</translation>
    </message>
</context>
<context>
    <name>stylos::app::CommandLine</name>
    <message>
        <source>Stylos, a workbench for very large 3D scans of monuments. With no file, opens the demo scene.</source>
        <translation>Stylos, ένα εργαλείο για πολύ μεγάλες τρισδιάστατες σαρώσεις μνημείων. Χωρίς αρχείο, ανοίγει τη σκηνή επίδειξης.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>αρχείο</translation>
    </message>
    <message>
        <source>Wait until the scene and its tasks are ready and the view is refined, save the window as a PNG image to &lt;file&gt; and exit (status 1 if something failed).</source>
        <translation>Αναμονή μέχρι να είναι έτοιμες η σκηνή και οι εργασίες της και να εκλεπτυνθεί η προβολή, αποθήκευση του παραθύρου ως εικόνας PNG στο &lt;αρχείο&gt; και έξοδος (κατάσταση εξόδου 1 αν κάτι απέτυχε).</translation>
    </message>
    <message>
        <source>Orbit the camera for &lt;frames&gt; frames at 1280 × 800 once the scene is ready, print the frame times as JSON and exit.</source>
        <translation>Περιστροφή της κάμερας σε τροχιά για &lt;καρέ&gt; καρέ σε 1280 × 800 μόλις η σκηνή είναι έτοιμη, εκτύπωση των χρόνων καρέ ως JSON και έξοδος.</translation>
    </message>
    <message>
        <source>frames</source>
        <translation>καρέ</translation>
    </message>
    <message>
        <source>A project (.stylos), or scans to import (%1).</source>
        <translation>Ένα έργο (.stylos) ή σαρώσεις για εισαγωγή (%1).</translation>
    </message>
    <message>
        <source>--orbit-benchmark: &apos;%1&apos; is not a frame count (1 to 100000)</source>
        <translation>--orbit-benchmark: το «%1» δεν είναι πλήθος καρέ (1 έως 100000)</translation>
    </message>
    <message>
        <source>--orbit-benchmark needs exactly one file</source>
        <translation>το --orbit-benchmark απαιτεί ακριβώς ένα αρχείο</translation>
    </message>
    <message>
        <source>--grab and --orbit-benchmark do not go together</source>
        <translation>τα --grab και --orbit-benchmark δεν μπορούν να συνδυαστούν</translation>
    </message>
    <message>
        <source>Turn the first fragment, a change of its pose every frame, for &lt;frames&gt; frames at 1280 × 800 once the scene is ready, print the frame times as JSON and exit.</source>
        <translation>Περιστροφή του πρώτου θραύσματος, με αλλαγή της θέσης του σε κάθε καρέ, για &lt;καρέ&gt; καρέ σε 1280 × 800 μόλις η σκηνή είναι έτοιμη, εκτύπωση των χρόνων καρέ ως JSON και έξοδος.</translation>
    </message>
    <message>
        <source>--pose-benchmark: &apos;%1&apos; is not a frame count (1 to 100000)</source>
        <translation>--pose-benchmark: το «%1» δεν είναι πλήθος καρέ (1 έως 100000)</translation>
    </message>
    <message>
        <source>--pose-benchmark needs exactly one file</source>
        <translation>το --pose-benchmark απαιτεί ακριβώς ένα αρχείο</translation>
    </message>
    <message>
        <source>--pose-benchmark goes with neither --grab nor --orbit-benchmark</source>
        <translation>το --pose-benchmark δεν συνδυάζεται ούτε με το --grab ούτε με το --orbit-benchmark</translation>
    </message>
    <message>
        <source>With --grab: first fit the first fragment&apos;s drum guides, dock against it and show the Move tool on the second fragment, in the drum&apos;s frame.</source>
        <translation>Με --grab: πρώτα προσαρμογή των οδηγών σπονδύλου του πρώτου θραύσματος, πρόσδεση σε αυτό και εμφάνιση του εργαλείου Μετακίνησης στο δεύτερο θραύσμα, στο σύστημα του σπονδύλου.</translation>
    </message>
    <message>
        <source>--gizmo goes with --grab</source>
        <translation>Το --gizmo χρησιμοποιείται με το --grab</translation>
    </message>
    <message>
        <source>With --grab: first fit the first fragment&apos;s drum guides, dock the second fragment to its flutes from where it stands and show its contact readout.</source>
        <translation>Με --grab: πρώτα προσαρμογή των οδηγών σπονδύλου του πρώτου θραύσματος, πρόσδεση του δεύτερου θραύσματος στις ραβδώσεις του από τη θέση του και εμφάνιση της ένδειξης επαφής του.</translation>
    </message>
    <message>
        <source>--dock goes with --grab</source>
        <translation>το --dock χρησιμοποιείται με το --grab</translation>
    </message>
    <message>
        <source>--dock and --gizmo do not go together</source>
        <translation>τα --dock και --gizmo δεν συνδυάζονται</translation>
    </message>
    <message>
        <source>With --grab: first label three regions of the first fragment with the 3D lasso (preserved marble, fractured marble, plaster) and show the Annotation shading.</source>
        <translation>Με --grab: πρώτα επισήμανση τριών περιοχών του πρώτου θραύσματος με το 3Δ λάσο (σωζόμενο μάρμαρο, θραυσμένο μάρμαρο, γύψος) και εμφάνιση της σκίασης Σχολιασμός.</translation>
    </message>
    <message>
        <source>--annotation goes with --grab alone</source>
        <translation>το --annotation πάει μόνο με το --grab</translation>
    </message>
    <message>
        <source>--paint goes with --grab</source>
        <translation>το --paint χρησιμοποιείται με το --grab</translation>
    </message>
    <message>
        <source>With --grab: paint as --paint, then write the first fragment&apos;s plate (its développée and front view at 1:N) to BASE.pdf and BASE.png, and grab the Export plate dialog.</source>
        <translation>Με --grab: ζωγραφίζει όπως το --paint, μετά γράφει τον πίνακα του πρώτου θραύσματος (το ανάπτυγμα και την πρόσοψή του σε 1:N) στα BASE.pdf και BASE.png και καταγράφει το παράθυρο Εξαγωγή πίνακα.</translation>
    </message>
    <message>
        <source>--plate goes with --grab alone</source>
        <translation>Το --plate πάει μόνο με το --grab</translation>
    </message>
    <message>
        <source>With --grab: first compute the first fragment&apos;s développée and paint a few annotation regions on it (marble, fractured marble, plaster; a claw-chisel area in the tool-mark layer). With --dock too: after the dock, the développée of the second fragment&apos;s assembly, painted across the drum and the fragment.</source>
        <translation>Με --grab: πρώτα υπολογισμός της ανάπτυξης του πρώτου θραύσματος και βαφή μερικών περιοχών σχολιασμού σε αυτήν (μάρμαρο, θραυσμένο μάρμαρο, γύψος· μια περιοχή οδοντωτής σμίλης στο επίπεδο ιχνών εργαλείου). Και με --dock: μετά την προσάρτηση, η ανάπτυξη της συναρμολόγησης του δεύτερου θραύσματος, βαμμένη πάνω στον σπόνδυλο και στο θραύσμα.</translation>
    </message>
    <message>
        <source>--paint does not go with --gizmo or --annotation</source>
        <translation>Το --paint δεν συνδυάζεται με --gizmo ή --annotation</translation>
    </message>
</context>
<context>
    <name>stylos::app::DeveloppeeDock</name>
    <message>
        <source>Développée</source>
        <translation>Ανάπτυγμα</translation>
    </message>
</context>
<context>
    <name>stylos::app::DeveloppeeLink</name>
    <message>
        <source>Développée of %1 cancelled</source>
        <translation>Το ανάπτυγμα του %1 ακυρώθηκε</translation>
    </message>
    <message>
        <source>The développée of %1 needs a drum with an axis guide (Use as the assembly&apos;s drum)</source>
        <translation>Το ανάπτυγμα του %1 χρειάζεται σπόνδυλο με οδηγό άξονα (Χρήση ως σπονδύλου της συναρμολόγησης)</translation>
    </message>
    <message>
        <source>The développée of %1 cannot start: its drum is still opening or busy</source>
        <translation>Το ανάπτυγμα του %1 δεν μπορεί να ξεκινήσει: ο σπόνδυλός του ανοίγει ακόμη ή είναι απασχολημένος</translation>
    </message>
    <message>
        <source>Développée of %1: %2</source>
        <translation>Ανάπτυγμα του %1: %2</translation>
    </message>
    <message>
        <source>%1 is unrolled about its drum&apos;s axis guide and does not stand on the drum yet: dock it first, or untick Use the axis guide to unroll it about a cylinder fitted to itself.</source>
        <translation>Το %1 αναπτύσσεται γύρω από τον οδηγό άξονα του σπονδύλου του και δεν βρίσκεται ακόμη πάνω στον σπόνδυλο: προσδέστε το πρώτα, ή αποεπιλέξτε τη «Χρήση του οδηγού άξονα» για να αναπτυχθεί γύρω από κύλινδρο προσαρμοσμένο στο ίδιο.</translation>
    </message>
</context>
<context>
    <name>stylos::app::DisplaySettingsWidget</name>
    <message>
        <source>Headlight</source>
        <translation>Φως κάμερας</translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation>Θόλος ουρανού</translation>
    </message>
    <message>
        <source>Scan colour</source>
        <translation>Χρώμα σάρωσης</translation>
    </message>
    <message>
        <source> ×</source>
        <translation> ×</translation>
    </message>
    <message>
        <source> M points</source>
        <translation> εκ. σημεία</translation>
    </message>
    <message>
        <source>Points drawn at most; the view refines up to it when the camera stops</source>
        <translation>Μέγιστο πλήθος σημείων που σχεδιάζονται· η προβολή εκλεπτύνεται έως αυτό όταν η κάμερα σταματά</translation>
    </message>
    <message>
        <source>View-dependent</source>
        <translation>Ανάλογα με την προβολή</translation>
    </message>
    <message>
        <source>Global level</source>
        <translation>Καθολικό επίπεδο</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Σκίαση</translation>
    </message>
    <message>
        <source>Splat size</source>
        <translation>Μέγεθος κηλίδων</translation>
    </message>
    <message>
        <source>Point budget</source>
        <translation>Όριο σημείων</translation>
    </message>
    <message>
        <source>Level of detail</source>
        <translation>Επίπεδο λεπτομέρειας</translation>
    </message>
    <message>
        <source>Size of the drawn points, as a multiple of the size of their octree cell</source>
        <translation>Μέγεθος των σημείων που σχεδιάζονται, ως πολλαπλάσιο του μεγέθους του κελιού τους στο οκταδικό δέντρο</translation>
    </message>
    <message>
        <source>View-dependent: finer cells near the camera, within the point budget; global level: every fragment drawn at the one octree level below</source>
        <translation>Κατά την όψη: λεπτότερα κελιά κοντά στην κάμερα, εντός του ορίου σημείων· καθολικό επίπεδο: κάθε θραύσμα σχεδιάζεται στο ένα επίπεδο οκταδικού δέντρου παρακάτω</translation>
    </message>
    <message>
        <source>The octree level drawn when the level of detail is global (0: the root cell)</source>
        <translation>Το επίπεδο του οκταδικού δέντρου που σχεδιάζεται όταν το επίπεδο λεπτομέρειας είναι καθολικό (0: το κελί ρίζα)</translation>
    </message>
    <message>
        <source>Octree level</source>
        <translation>Επίπεδο δέντρου</translation>
    </message>
    <message>
        <source>Eye-dome lighting</source>
        <translation>Φωτισμός eye-dome (EDL)</translation>
    </message>
    <message>
        <source>Annotation</source>
        <translation>Σχολιασμός</translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation>Υλικό / κατάσταση</translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation>Ίχνη εργαλείου</translation>
    </message>
    <message>
        <source>The layer the Annotation shading shows and the 3D lasso labels</source>
        <translation>Το επίπεδο που δείχνει η σκίαση Σχολιασμός και επισημαίνει το 3Δ λάσο</translation>
    </message>
    <message>
        <source>Annotation layer</source>
        <translation>Επίπεδο σχολιασμού</translation>
    </message>
    <message>
        <source>How the points are lit: by a light at the eye (headlight), by the sky each cell sees (skydome; needs Tools › Compute skydome, else the headlight), in the scan&apos;s colours, by eye-dome lighting (the relief from the depth alone), or tinted by each cell&apos;s class in the annotation layer below</source>
        <translation>Πώς φωτίζονται τα σημεία: με φως στο μάτι (προβολέας), με τον ουρανό που βλέπει κάθε κελί (skydome· απαιτεί Εργαλεία › Υπολογισμός skydome, αλλιώς ο προβολέας), με τα χρώματα της σάρωσης, με φωτισμό eye-dome (το ανάγλυφο μόνο από το βάθος), ή χρωματισμένα κατά την κλάση κάθε κελιού στο στρώμα σχολιασμού παρακάτω</translation>
    </message>
    <message>
        <source>Close the small gaps between the drawn points on screen, and hide a far surface seen through a narrow gap in a nearer one, when the view stops; openings of the scan wider than the points stay open</source>
        <translation>Κλείνει στην οθόνη τα μικρά κενά ανάμεσα στα σχεδιασμένα σημεία και κρύβει μια μακρινή επιφάνεια που φαίνεται μέσα από στενό κενό μιας πλησιέστερης, όταν η προβολή σταματά· τα ανοίγματα της σάρωσης που είναι φαρδύτερα από τα σημεία μένουν ανοιχτά</translation>
    </message>
    <message>
        <source>Fill gaps</source>
        <translation>Κάλυψη κενών</translation>
    </message>
</context>
<context>
    <name>stylos::app::DockingActions</name>
    <message>
        <source>Docking against %1</source>
        <translation>Πρόσδεση στο %1</translation>
    </message>
    <message>
        <source>The guides of this fragment are being fitted already, or its octree is not open yet</source>
        <translation>Οι οδηγοί αυτού του θραύσματος προσαρμόζονται ήδη, ή το octree του δεν έχει ανοίξει ακόμη</translation>
    </message>
    <message>
        <source>Guides of %1: %2 flutes, leading radius %3 mm, flute depth %4 mm, RMS %5 mm, %6 s</source>
        <translation>Οδηγοί του %1: %2 ραβδώσεις, κύρια ακτίνα %3 mm, βάθος ραβδώσεων %4 mm, RMS %5 mm, %6 s</translation>
    </message>
    <message>
        <source>&amp;Move tool</source>
        <translation>Εργαλείο &amp;Μετακίνησης</translation>
    </message>
    <message>
        <source>Move the selected fragment with arrows and rings in the 3D view; Shift: finer, Ctrl: by degrees, Alt: tilts, L: the next frame, Escape: cancel the drag</source>
        <translation>Μετακίνηση του επιλεγμένου θραύσματος με βέλη και δακτυλίους στην τρισδιάστατη προβολή· Shift: λεπτότερα, Ctrl: ανά μοίρα, Alt: κλίσεις, L: επόμενο σύστημα, Escape: ακύρωση της σύρσης</translation>
    </message>
    <message>
        <source>Gizmo &amp;frame</source>
        <translation>&amp;Σύστημα χειριστηρίου</translation>
    </message>
    <message>
        <source>&amp;World</source>
        <translation>&amp;Κόσμος</translation>
    </message>
    <message>
        <source>&amp;Fragment</source>
        <translation>&amp;Θραύσμα</translation>
    </message>
    <message>
        <source>&amp;Drum</source>
        <translation>&amp;Σπόνδυλος</translation>
    </message>
    <message>
        <source>Dock against this &amp;drum</source>
        <translation>Πρόσδεση σε αυτόν τον &amp;σπόνδυλο</translation>
    </message>
    <message>
        <source>Use the axis and flutes of the selected fragment for the gizmo&apos;s Drum frame</source>
        <translation>Χρήση του άξονα και των ραβδώσεων του επιλεγμένου θραύσματος για το σύστημα Σπονδύλου του χειριστηρίου</translation>
    </message>
    <message>
        <source>Fit drum &amp;guides</source>
        <translation>Προσαρμογή &amp;οδηγών σπονδύλου</translation>
    </message>
    <message>
        <source>Fit the axis and the flute lines of the selected drum in the background</source>
        <translation>Προσαρμογή στο παρασκήνιο του άξονα και των γραμμών ραβδώσεων του επιλεγμένου σπονδύλου</translation>
    </message>
    <message>
        <source>De&amp;lete guides</source>
        <translation>&amp;Διαγραφή οδηγών</translation>
    </message>
    <message>
        <source>Remove the axis and flute guides of the selected fragment</source>
        <translation>Αφαίρεση των οδηγών άξονα και ραβδώσεων του επιλεγμένου θραύσματος</translation>
    </message>
    <message>
        <source>Show &amp;guides</source>
        <translation>Εμφάνιση &amp;οδηγών</translation>
    </message>
    <message>
        <source>This fragment is being docked already, or its octree or the drum&apos;s is not open yet</source>
        <translation>Το θραύσμα αυτό προσδένεται ήδη, ή το οκταδικό δέντρο του ή του σπονδύλου δεν έχει ανοίξει ακόμη</translation>
    </message>
    <message>
        <source>Dock to &amp;flutes</source>
        <translation>Πρόσδεση στις &amp;ραβδώσεις</translation>
    </message>
    <message>
        <source>Snap the selected fragment onto the nearest flutes of the docking drum and refine its pose against them (one undo step)</source>
        <translation>Ευθυγράμμιση του επιλεγμένου θραύσματος στις πλησιέστερες ραβδώσεις του σπονδύλου πρόσδεσης και βελτίωση της θέσης του πάνω τους (ένα βήμα αναίρεσης)</translation>
    </message>
    <message>
        <source>Docking &amp;locks</source>
        <translation>&amp;Κλειδώματα πρόσδεσης</translation>
    </message>
    <message>
        <source>Lock &amp;z (along the axis)</source>
        <translation>Κλείδωμα &amp;z (κατά μήκος του άξονα)</translation>
    </message>
    <message>
        <source>Lock &amp;r (radial)</source>
        <translation>Κλείδωμα &amp;r (ακτινικά)</translation>
    </message>
    <message>
        <source>Lock &amp;θ (about the axis)</source>
        <translation>Κλείδωμα &amp;θ (γύρω από τον άξονα)</translation>
    </message>
    <message>
        <source>Lock &amp;tilts</source>
        <translation>Κλείδωμα &amp;κλίσεων</translation>
    </message>
    <message>
        <source>Set &amp;axis from two points</source>
        <translation>Ορισμός &amp;άξονα από δύο σημεία</translation>
    </message>
    <message>
        <source>Click two points on the selected fragment in the 3D view: its axis guide goes through them (Escape cancels)</source>
        <translation>Κάντε κλικ σε δύο σημεία του επιλεγμένου θραύσματος στην τρισδιάστατη προβολή: ο οδηγός άξονά του περνά από αυτά (το Escape ακυρώνει)</translation>
    </message>
    <message>
        <source>&amp;Edit axis…</source>
        <translation>&amp;Επεξεργασία άξονα…</translation>
    </message>
    <message>
        <source>Type the point and direction of the selected fragment&apos;s axis guide</source>
        <translation>Πληκτρολογήστε το σημείο και την κατεύθυνση του οδηγού άξονα του επιλεγμένου θραύσματος</translation>
    </message>
    <message>
        <source>&amp;Reverse axis</source>
        <translation>&amp;Αντιστροφή άξονα</translation>
    </message>
    <message>
        <source>Turn the selected fragment&apos;s axis guide end for end: a drum lying on its side whose développée came out upside down unrolls the right way up</source>
        <translation>Αντιστροφή του οδηγού άξονα του επιλεγμένου θραύσματος: ένας πλαγιασμένος σπόνδυλος του οποίου το ανάπτυγμα βγήκε ανάποδα αναπτύσσεται σωστά</translation>
    </message>
</context>
<context>
    <name>stylos::app::LegendDock</name>
    <message>
        <source>Legend</source>
        <translation>Υπόμνημα</translation>
    </message>
</context>
<context>
    <name>stylos::app::LogDock</name>
    <message>
        <source>Log</source>
        <translation>Καταγραφή</translation>
    </message>
</context>
<context>
    <name>stylos::app::MainActions</name>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Βοήθεια</translation>
    </message>
    <message>
        <source>Open &amp;demo</source>
        <translation>Άνοιγμα &amp;επίδειξης</translation>
    </message>
    <message>
        <source>&amp;About Stylos</source>
        <translation>&amp;Σχετικά με το Stylos</translation>
    </message>
    <message>
        <source>About Stylos</source>
        <translation>Σχετικά με το Stylos</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;A workbench for very large 3D scans of monuments: column drums, capitals, fragments.&lt;/p&gt;&lt;p&gt;Point-based, after Duguet, Drettakis, Girardeau-Montaut, Martinez and Schneider (VAST 2004).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Stylos %1&lt;/h3&gt;&lt;p&gt;Ένα εργαλείο για πολύ μεγάλες τρισδιάστατες σαρώσεις μνημείων: σπόνδυλοι κιόνων, κιονόκρανα, θραύσματα.&lt;/p&gt;&lt;p&gt;Βασισμένο σε σημεία, κατά τους Duguet, Drettakis, Girardeau-Montaut, Martinez και Schneider (VAST 2004).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Επεξεργασία</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Προβολή</translation>
    </message>
    <message>
        <source>Standard &amp;views</source>
        <translation>&amp;Τυπικές όψεις</translation>
    </message>
    <message>
        <source>&amp;Shading</source>
        <translation>&amp;Σκίαση</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>Ε&amp;ργαλεία</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Γλώσσα</translation>
    </message>
    <message>
        <source>Undo the last change to the scene</source>
        <translation>Αναίρεση της τελευταίας αλλαγής στη σκηνή</translation>
    </message>
    <message>
        <source>Redo the change undone last</source>
        <translation>Επανάληψη της αλλαγής που αναιρέθηκε τελευταία</translation>
    </message>
    <message>
        <source>&amp;Remove from the scene</source>
        <translation>&amp;Αφαίρεση από τη σκηνή</translation>
    </message>
    <message>
        <source>&amp;Fit to the scene</source>
        <translation>&amp;Προσαρμογή στη σκηνή</translation>
    </message>
    <message>
        <source>Fit to the &amp;selection</source>
        <translation>Προσαρμογή στην &amp;επιλογή</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Εμπρόσθια</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Οπίσθια</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Αριστερή</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Δεξιά</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Άνω</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>Κάτω</translation>
    </message>
    <message>
        <source>Isometric</source>
        <translation>Ισομετρική</translation>
    </message>
    <message>
        <source>&amp;Orthographic</source>
        <translation>&amp;Ορθογραφική προβολή</translation>
    </message>
    <message>
        <source>&amp;Headlight</source>
        <translation>&amp;Φως κάμερας</translation>
    </message>
    <message>
        <source>S&amp;kydome</source>
        <translation>&amp;Θόλος ουρανού</translation>
    </message>
    <message>
        <source>Scan &amp;colour</source>
        <translation>&amp;Χρώμα σάρωσης</translation>
    </message>
    <message>
        <source>Compute &amp;skydome</source>
        <translation>&amp;Υπολογισμός θόλου ουρανού</translation>
    </message>
    <message>
        <source>Compute the 3D skydome (ambient occlusion) of the selected fragments in the background; the view then shades them by it</source>
        <translation>Υπολογισμός στο παρασκήνιο του τρισδιάστατου θόλου ουρανού (απόκρυψη περιβάλλοντος) των επιλεγμένων θραυσμάτων· η προβολή τα σκιάζει στη συνέχεια με βάση αυτόν</translation>
    </message>
    <message>
        <source>&amp;Développée</source>
        <translation>&amp;Ανάπτυγμα</translation>
    </message>
    <message>
        <source>Unroll the selected fragment in the Développée dock</source>
        <translation>Ξετύλιγμα του επιλεγμένου θραύσματος στο πλαίσιο Ανάπτυγμα</translation>
    </message>
    <message>
        <source>Open the demo scene: a fluted drum, two of its fragments and an omphalos</source>
        <translation>Άνοιγμα της σκηνής επίδειξης: ένας ραβδωτός σπόνδυλος, δύο θραύσματά του και ένας ομφαλός</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Γλώσσα συστήματος</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Αναίρεση</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Αναίρεση: %1</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Ε&amp;πανάληψη</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>Ε&amp;πανάληψη: %1</translation>
    </message>
    <message>
        <source>&amp;Eye-dome lighting</source>
        <translation>Φωτισμός &amp;eye-dome (EDL)</translation>
    </message>
    <message>
        <source>&amp;Annotation</source>
        <translation>Σ&amp;χολιασμός</translation>
    </message>
    <message>
        <source>Undo</source>
        <comment>toolbar</comment>
        <translation>Αναίρεση</translation>
    </message>
    <message>
        <source>Redo</source>
        <comment>toolbar</comment>
        <translation>Επανάληψη</translation>
    </message>
    <message>
        <source>Fit</source>
        <comment>toolbar</comment>
        <translation>Προσαρμογή</translation>
    </message>
    <message>
        <source>Orthographic</source>
        <comment>toolbar</comment>
        <translation>Ορθογραφική</translation>
    </message>
    <message>
        <source>Skydome</source>
        <comment>toolbar</comment>
        <translation>Θόλος ουρανού</translation>
    </message>
    <message>
        <source>Développée</source>
        <comment>toolbar</comment>
        <translation>Ανάπτυγμα</translation>
    </message>
</context>
<context>
    <name>stylos::app::MainWindow</name>
    <message>
        <source>Stylos</source>
        <translation>Stylos</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1 (%2)</translation>
    </message>
    <message numerus="yes">
        <source>Remove %n fragment(s)</source>
        <translation>
            <numerusform>Αφαίρεση %n θραύσματος</numerusform>
            <numerusform>Αφαίρεση %n θραυσμάτων</numerusform>
        </translation>
    </message>
    <message>
        <source>Imported %1</source>
        <translation>Εισήχθη: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n scan(s) could not be imported:</source>
        <translation>
            <numerusform>Δεν ήταν δυνατή η εισαγωγή %n σάρωσης:</numerusform>
            <numerusform>Δεν ήταν δυνατή η εισαγωγή %n σαρώσεων:</numerusform>
        </translation>
    </message>
    <message>
        <source>The skydome of the selection is being computed already, or its octrees are not open yet</source>
        <translation>Ο θόλος ουρανού της επιλογής υπολογίζεται ήδη ή τα οκταδικά δέντρα της δεν έχουν ανοίξει ακόμη</translation>
    </message>
    <message>
        <source>%1[*] — Stylos</source>
        <translation>%1[*] — Stylos</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Αρχείο</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>Κύρια γραμμή εργαλείων</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.3 (core profile), which this display does not offer.</source>
        <translation>Η τρισδιάστατη προβολή απαιτεί OpenGL 3.3 (core profile), το οποίο δεν παρέχει αυτή η οθόνη.</translation>
    </message>
    <message>
        <source>Skydome of %1: %2 cells at level %3, %4 sky directions, %5 s</source>
        <translation>Θόλος ουρανού του %1: %2 κελιά στο επίπεδο %3, %4 κατευθύνσεις ουρανού, %5 s</translation>
    </message>
    <message>
        <source>View and tools toolbar</source>
        <translation>Γραμμή προβολής και εργαλείων</translation>
    </message>
    <message>
        <source>Could not compute the skydome of %1: its octree %2 does not exist</source>
        <translation>Δεν υπολογίστηκε ο θόλος ουρανού του %1: το octree του, %2, δεν υπάρχει</translation>
    </message>
</context>
<context>
    <name>stylos::app::PlateActions</name>
    <message>
        <source>Export &amp;plate…</source>
        <translation>Εξαγωγή &amp;πίνακα…</translation>
    </message>
    <message>
        <source>A publication plate at an exact scale: développées and orthographic views at 1:N with scale bars, legend and caption, as PDF, SVG, TIFF or PNG</source>
        <translation>Πίνακας δημοσίευσης σε ακριβή κλίμακα: αναπτύγματα και ορθογραφικές όψεις σε 1:N με γραφικές κλίμακες, υπόμνημα και λεζάντα, ως PDF, SVG, TIFF ή PNG</translation>
    </message>
    <message>
        <source>Export &amp;développée image…</source>
        <translation>Εξαγωγή εικόνας &amp;αναπτύγματος…</translation>
    </message>
    <message>
        <source>The développée on show as PNG or TIFF with its pixel size, and its map (.json) beside it</source>
        <translation>Το εμφανιζόμενο ανάπτυγμα ως PNG ή TIFF με το μέγεθος εικονοστοιχείου του, και η αντιστοιχία του (.json) δίπλα</translation>
    </message>
    <message>
        <source>Export plate</source>
        <translation>Εξαγωγή πίνακα</translation>
    </message>
    <message>
        <source>PDF (*.pdf);;SVG (*.svg);;TIFF (*.tif *.tiff);;PNG (*.png)</source>
        <translation>PDF (*.pdf);;SVG (*.svg);;TIFF (*.tif *.tiff);;PNG (*.png)</translation>
    </message>
    <message>
        <source>Drawing the plate %1</source>
        <translation>Σχεδίαση του πίνακα %1</translation>
    </message>
    <message>
        <source>Drawing the plate was cancelled</source>
        <translation>Η σχεδίαση του πίνακα ακυρώθηκε</translation>
    </message>
    <message>
        <source>Wrote the plate %1</source>
        <translation>Γράφτηκε ο πίνακας %1</translation>
    </message>
    <message>
        <source>Could not draw the plate: %1</source>
        <translation>Δεν ήταν δυνατή η σχεδίαση του πίνακα: %1</translation>
    </message>
    <message>
        <source>There is no développée to export: compute one first (Tools › Développée)</source>
        <translation>Δεν υπάρχει ανάπτυγμα για εξαγωγή: υπολογίστε πρώτα ένα (Εργαλεία › Ανάπτυγμα)</translation>
    </message>
    <message>
        <source>Export développée image</source>
        <translation>Εξαγωγή εικόνας αναπτύγματος</translation>
    </message>
    <message>
        <source>PNG (*.png);;TIFF (*.tif *.tiff)</source>
        <translation>PNG (*.png);;TIFF (*.tif *.tiff)</translation>
    </message>
    <message>
        <source>Could not export the développée: %1</source>
        <translation>Δεν ήταν δυνατή η εξαγωγή του αναπτύγματος: %1</translation>
    </message>
    <message>
        <source>Could not write the développée&apos;s map: %1</source>
        <translation>Δεν ήταν δυνατή η εγγραφή της αντιστοιχίας του αναπτύγματος: %1</translation>
    </message>
    <message>
        <source>Wrote the développée %1 and its map</source>
        <translation>Γράφτηκε το ανάπτυγμα %1 και η αντιστοιχία του</translation>
    </message>
    <message>
        <source>Export &amp;view image…</source>
        <translation>Εξαγωγή εικόνας &amp;όψης…</translation>
    </message>
    <message>
        <source>The visible fragments seen along the 3D view&apos;s direction, orthographic, every cell drawn, at a width you choose, as PNG or TIFF</source>
        <translation>Τα ορατά θραύσματα κατά την κατεύθυνση της τρισδιάστατης όψης, ορθογραφικά, κάθε κελί σχεδιασμένο, στο πλάτος που επιλέγετε, ως PNG ή TIFF</translation>
    </message>
    <message>
        <source>Export view image</source>
        <translation>Εξαγωγή εικόνας όψης</translation>
    </message>
    <message>
        <source>There is no 3D view to export</source>
        <translation>Δεν υπάρχει τρισδιάστατη όψη για εξαγωγή</translation>
    </message>
    <message>
        <source>Rendering the view %1</source>
        <translation>Απόδοση της όψης %1</translation>
    </message>
    <message>
        <source>Wrote the view image %1</source>
        <translation>Γράφτηκε η εικόνα όψης %1</translation>
    </message>
    <message>
        <source>Width in pixels (the whole image at most %L1 million pixels)</source>
        <translation>Πλάτος σε εικονοστοιχεία (όλη η εικόνα το πολύ %L1 εκατομμύρια εικονοστοιχεία)</translation>
    </message>
    <message>
        <source>Rendering the view image %1 was cancelled</source>
        <translation>Η απόδοση της εικόνας της προβολής %1 ακυρώθηκε</translation>
    </message>
    <message>
        <source>Could not render the view image %1: %2</source>
        <translation>Αδύνατη η απόδοση της εικόνας της προβολής %1: %2</translation>
    </message>
</context>
<context>
    <name>stylos::app::ProjectActions</name>
    <message>
        <source>&amp;New project</source>
        <translation>&amp;Νέο έργο</translation>
    </message>
    <message>
        <source>&amp;Open project…</source>
        <translation>&amp;Άνοιγμα έργου…</translation>
    </message>
    <message>
        <source>Open a Stylos project (.stylos)</source>
        <translation>Άνοιγμα έργου Stylos (.stylos)</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Άνοιγμα &amp;πρόσφατου</translation>
    </message>
    <message>
        <source>&amp;Save project</source>
        <translation>Απο&amp;θήκευση έργου</translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation>Αποθήκευση έργου &amp;ως…</translation>
    </message>
    <message>
        <source>&amp;Import scans…</source>
        <translation>&amp;Εισαγωγή σαρώσεων…</translation>
    </message>
    <message>
        <source>Build a packed octree of each scan in the background and add it to the scene</source>
        <translation>Δημιουργία στο παρασκήνιο ενός συμπαγούς οκταδικού δέντρου για κάθε σάρωση και προσθήκη του στη σκηνή</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>Έ&amp;ξοδος</translation>
    </message>
    <message>
        <source>%1: a project opens alone, not with other files</source>
        <translation>%1: ένα έργο ανοίγει μόνο του, όχι μαζί με άλλα αρχεία</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Άνοιξε το έργο %1</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Αποθηκεύτηκε το έργο %1</translation>
    </message>
    <message>
        <source>Save project</source>
        <translation>Αποθήκευση έργου</translation>
    </message>
    <message>
        <source>Stylos projects (*.stylos)</source>
        <translation>Έργα Stylos (*.stylos)</translation>
    </message>
    <message>
        <source>Stylos</source>
        <translation>Stylos</translation>
    </message>
    <message>
        <source>The project %1 has unsaved changes.</source>
        <translation>Το έργο %1 έχει μη αποθηκευμένες αλλαγές.</translation>
    </message>
    <message>
        <source>Open project</source>
        <translation>Άνοιγμα έργου</translation>
    </message>
    <message>
        <source>Import scans</source>
        <translation>Εισαγωγή σαρώσεων</translation>
    </message>
    <message>
        <source>No recent project</source>
        <translation>Κανένα πρόσφατο έργο</translation>
    </message>
    <message>
        <source>Clear the list</source>
        <translation>Εκκαθάριση λίστας</translation>
    </message>
    <message numerus="yes">
        <source>The project uses %n octree(s) outside its folder, %1 in all.</source>
        <translation>
            <numerusform>Το έργο χρησιμοποιεί %n οκταδικό δέντρο εκτός του φακέλου του, %1 συνολικά.</numerusform>
            <numerusform>Το έργο χρησιμοποιεί %n οκταδικά δέντρα εκτός του φακέλου του, %1 συνολικά.</numerusform>
        </translation>
    </message>
    <message>
        <source>Copied into the folder, they travel with it: the folder can be moved or copied whole. Left where they are, the project names them there.</source>
        <translation>Αντιγραμμένα στον φάκελο, ταξιδεύουν μαζί του: ο φάκελος μπορεί να μετακινηθεί ή να αντιγραφεί ολόκληρος. Αν μείνουν όπου είναι, το έργο τα αναφέρει εκεί.</translation>
    </message>
    <message>
        <source>Copy into the folder</source>
        <translation>Αντιγραφή στον φάκελο</translation>
    </message>
    <message>
        <source>Leave them where they are</source>
        <translation>Να μείνουν όπου είναι</translation>
    </message>
    <message numerus="yes">
        <source>Saved %1, with %n octree(s) copied into its folder</source>
        <translation>
            <numerusform>Αποθηκεύτηκε το %1, με %n οκταδικό δέντρο αντιγραμμένο στον φάκελό του</numerusform>
            <numerusform>Αποθηκεύτηκε το %1, με %n οκταδικά δέντρα αντιγραμμένα στον φάκελό του</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Removed %n unused octree(s) from the cache, %1 freed</source>
        <translation>
            <numerusform>Αφαιρέθηκε %n αχρησιμοποίητο οκταδικό δέντρο από την κρυφή μνήμη, ελευθερώθηκαν %1</numerusform>
            <numerusform>Αφαιρέθηκαν %n αχρησιμοποίητα οκταδικά δέντρα από την κρυφή μνήμη, ελευθερώθηκαν %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Open</source>
        <comment>toolbar</comment>
        <translation>Άνοιγμα</translation>
    </message>
    <message>
        <source>Save</source>
        <comment>toolbar</comment>
        <translation>Αποθήκευση</translation>
    </message>
    <message>
        <source>Import</source>
        <comment>toolbar</comment>
        <translation>Εισαγωγή</translation>
    </message>
    <message>
        <source>The demo is rebuilt when it is opened again: save your work as a project of your own.</source>
        <translation>Η επίδειξη ξαναχτίζεται όταν ανοίγει ξανά: αποθηκεύστε την εργασία σας σε δικό σας έργο.</translation>
    </message>
    <message>
        <source>Could not save %1: it is in the demo&apos;s folder, rebuilt when the demo is opened again. Choose another folder.</source>
        <translation>Αδύνατη η αποθήκευση του %1: βρίσκεται στον φάκελο της επίδειξης, που ξαναχτίζεται όταν ανοίγει ξανά. Επιλέξτε άλλο φάκελο.</translation>
    </message>
</context>
<context>
    <name>stylos::app::PropertiesDock</name>
    <message>
        <source>Properties</source>
        <translation>Ιδιότητες</translation>
    </message>
    <message>
        <source>Fragment</source>
        <translation>Θραύσμα</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Εμφάνιση</translation>
    </message>
    <message>
        <source>Contact with the drum</source>
        <translation>Επαφή με τον σπόνδυλο</translation>
    </message>
    <message>
        <source>Placement in the drum frame</source>
        <translation>Θέση στο σύστημα του σπονδύλου</translation>
    </message>
</context>
<context>
    <name>stylos::app::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation>Σκηνή</translation>
    </message>
</context>
<context>
    <name>stylos::app::StatusReadout</name>
    <message>
        <source>x %1  y %2  z %3 m</source>
        <translation>x %1  y %2  z %3 m</translation>
    </message>
    <message>
        <source>%1 fps · %2 ms · %3 M points</source>
        <translation>%1 fps · %2 ms · %3 εκ. σημεία</translation>
    </message>
</context>
<context>
    <name>stylos::app::TasksDock</name>
    <message>
        <source>Tasks</source>
        <translation>Εργασίες</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AddFragmentCommand</name>
    <message>
        <source>Add %1</source>
        <translation>Προσθήκη %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AssemblyDeveloppeeJob</name>
    <message>
        <source>Développée of %1</source>
        <translation>Ανάπτυγμα του %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::AxisGuideEditor</name>
    <message>
        <source>Set axis cancelled</source>
        <translation>Ο ορισμός του άξονα ακυρώθηκε</translation>
    </message>
    <message>
        <source>Click two points on %1 for its axis (Escape cancels)</source>
        <translation>Κάντε κλικ σε δύο σημεία του %1 για τον άξονά του (το Escape ακυρώνει)</translation>
    </message>
    <message>
        <source>The two points picked on %1 are the same: pick two points apart along its axis</source>
        <translation>Τα δύο σημεία που επιλέχθηκαν στο %1 ταυτίζονται: επιλέξτε δύο σημεία σε απόσταση κατά μήκος του άξονά του</translation>
    </message>
    <message>
        <source>Set the axis of %1 from two points</source>
        <translation>Ορισμός του άξονα του %1 από δύο σημεία</translation>
    </message>
    <message>
        <source>Axis of %1 set through the two points picked, %2 mm apart</source>
        <translation>Ο άξονας του %1 ορίστηκε από τα δύο επιλεγμένα σημεία, σε απόσταση %2 mm</translation>
    </message>
    <message>
        <source>Edit the axis of %1</source>
        <translation>Επεξεργασία του άξονα του %1</translation>
    </message>
    <message>
        <source>Reverse the axis of %1</source>
        <translation>Αντιστροφή του άξονα του %1</translation>
    </message>
    <message>
        <source>The axis of %1 now points the other way: its développée turns upside down</source>
        <translation>Ο άξονας του %1 δείχνει τώρα προς την άλλη κατεύθυνση: το ανάπτυγμά του αναποδογυρίζει</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ClassMeasures</name>
    <message>
        <source>Areas of the classes of %1</source>
        <translation>Εμβαδά των κλάσεων του %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ContactJob</name>
    <message>
        <source>Contact of %1 with the drum</source>
        <translation>Επαφή του %1 με τον σπόνδυλο</translation>
    </message>
    <message>
        <source>Could not measure the contact of %1: %2.</source>
        <translation>Δεν ήταν δυνατή η μέτρηση της επαφής του %1: %2.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ContactReadoutWidget</name>
    <message>
        <source>Largest interpenetration:</source>
        <translation>Μέγιστη αλληλοδιείσδυση:</translation>
    </message>
    <message>
        <source>Median gap:</source>
        <translation>Διάμεσο κενό:</translation>
    </message>
    <message>
        <source>Gap, 90 % of points:</source>
        <translation>Κενό, 90 % των σημείων:</translation>
    </message>
    <message>
        <source>Gap, 99 % of points:</source>
        <translation>Κενό, 99 % των σημείων:</translation>
    </message>
    <message>
        <source>Within 0.5 mm:</source>
        <translation>Εντός 0,5 mm:</translation>
    </message>
    <message>
        <source>Points measured:</source>
        <translation>Σημεία που μετρήθηκαν:</translation>
    </message>
    <message>
        <source>Signed distance of the fragment&apos;s outer face to the drum&apos;s flute profile, along its normal; negative: inside the drum</source>
        <translation>Προσημασμένη απόσταση της εξωτερικής όψης του θραύσματος από το προφίλ των ραβδώσεων του σπονδύλου, κατά την κάθετό του· αρνητική: μέσα στον σπόνδυλο</translation>
    </message>
    <message>
        <source>Set a docking drum with guides (Tools › Dock against this drum) and select another fragment.</source>
        <translation>Ορίστε έναν σπόνδυλο πρόσδεσης με οδηγούς (Εργαλεία › Πρόσδεση σε αυτόν τον σπόνδυλο) και επιλέξτε άλλο θραύσμα.</translation>
    </message>
    <message>
        <source>Measuring…</source>
        <translation>Μέτρηση…</translation>
    </message>
    <message>
        <source>Against the docking drum&apos;s flute profile:</source>
        <translation>Έναντι του προφίλ ραβδώσεων του σπονδύλου πρόσδεσης:</translation>
    </message>
    <message>
        <source>The fragment does not touch the drum (no point of it within 5 mm of the profile).</source>
        <translation>Το θραύσμα δεν αγγίζει τον σπόνδυλο (κανένα σημείο του εντός 5 mm από το προφίλ).</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Against %1: %2</source>
        <translation>Έναντι του %1: %2</translation>
    </message>
    <message>
        <source>Against %1: no contact (no point within 5 mm)</source>
        <translation>Έναντι του %1: καμία επαφή (κανένα σημείο εντός 5 mm)</translation>
    </message>
    <message>
        <source>Against %1: largest interpenetration %2, median gap %3, 90 % gap %4 (%5 points)</source>
        <translation>Έναντι του %1: μέγιστη αλληλοδιείσδυση %2, διάμεσο κενό %3, κενό 90 % %4 (%5 σημεία)</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DemoScene</name>
    <message>
        <source>Could not create the demo folder %1.</source>
        <translation>Δεν ήταν δυνατή η δημιουργία του φακέλου επίδειξης %1.</translation>
    </message>
    <message>
        <source>Drum</source>
        <translation>Σπόνδυλος</translation>
    </message>
    <message>
        <source>Fragment A</source>
        <translation>Θραύσμα Α</translation>
    </message>
    <message>
        <source>Fragment B</source>
        <translation>Θραύσμα Β</translation>
    </message>
    <message>
        <source>Omphalos</source>
        <translation>Ομφαλός</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Άξονας</translation>
    </message>
    <message>
        <source>Preparing the demo scene</source>
        <translation>Προετοιμασία της σκηνής επίδειξης</translation>
    </message>
    <message>
        <source>Could not prepare the demo scene: %1: %2.</source>
        <translation>Δεν ήταν δυνατή η προετοιμασία της σκηνής επίδειξης: %1: %2.</translation>
    </message>
    <message>
        <source>Flute</source>
        <translation>Ράβδωση</translation>
    </message>
    <message>
        <source>Drum 1 reconstruction</source>
        <translation>Αναστήλωση σπονδύλου 1</translation>
    </message>
    <message>
        <source>Flute %1</source>
        <translation>Ράβδωση %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeAnnotator</name>
    <message>
        <source>Erase %1</source>
        <translation>Σβήσιμο %1</translation>
    </message>
    <message>
        <source>Paint “%1”</source>
        <translation>Βάψιμο «%1»</translation>
    </message>
    <message>
        <source>Not painted: the développée of the assembly is out of date (%1). Compute it again to paint.</source>
        <translation>Δεν βάφτηκε τίποτα: η ανάπτυξη της συναρμολόγησης δεν είναι πια ενημερωμένη (%1). Υπολογίστε την ξανά για να βάψετε.</translation>
    </message>
    <message>
        <source>its drum was removed</source>
        <translation>ο σπόνδυλός της αφαιρέθηκε</translation>
    </message>
    <message>
        <source>a fragment was removed</source>
        <translation>ένα θραύσμα αφαιρέθηκε</translation>
    </message>
    <message>
        <source>“%1” is no longer in the assembly</source>
        <translation>το «%1» δεν ανήκει πια στη συναρμολόγηση</translation>
    </message>
    <message>
        <source>“%1” was moved</source>
        <translation>το «%1» μετακινήθηκε</translation>
    </message>
    <message>
        <source>the octree of “%1” changed</source>
        <translation>το οκταδικό δέντρο του «%1» άλλαξε</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeJob</name>
    <message>
        <source>Développée of %1</source>
        <translation>Ανάπτυγμα του %1</translation>
    </message>
    <message>
        <source>Could not compute the développée of %1: %2.</source>
        <translation>Δεν ήταν δυνατός ο υπολογισμός του αναπτύγματος του %1: %2.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeePanel</name>
    <message>
        <source>%1: %2, radius %3 mm, RMS %4 mm, %5 % inliers; %6 × %7 pixels of %8 mm; %9 s</source>
        <translation>%1: %2, ακτίνα %3 mm, RMS %4 mm, %5 % σημεία εντός ανοχής· %6 × %7 εικονοστοιχεία των %8 mm· %9 s</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>Επιφάνεια</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Σκίαση</translation>
    </message>
    <message>
        <source>Pixel</source>
        <translation>Εικονοστοιχείο</translation>
    </message>
    <message>
        <source>The surface the développée is unrolled from</source>
        <translation>Η επιφάνεια από την οποία ξετυλίγεται το ανάπτυγμα</translation>
    </message>
    <message>
        <source>How the heights become grey: the sky each point sees, one light, or height</source>
        <translation>Πώς τα ύψη γίνονται τόνοι του γκρι: ο ουρανός που βλέπει κάθε σημείο, ένα φως ή το ύψος</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Αυτόματο</translation>
    </message>
    <message>
        <source>Side of a pixel; Automatic uses the octree&apos;s leaf size</source>
        <translation>Πλευρά ενός εικονοστοιχείου· το Αυτόματο χρησιμοποιεί το μέγεθος φύλλου του οκταδικού δέντρου</translation>
    </message>
    <message>
        <source>Use the axis guide</source>
        <translation>Χρήση του οδηγού άξονα</translation>
    </message>
    <message>
        <source>Fit only the radius about the fragment&apos;s axis guide (needed for a fragment)</source>
        <translation>Προσαρμογή μόνο της ακτίνας γύρω από τον οδηγό άξονα του θραύσματος (απαραίτητο για θραύσμα)</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Προσαρμογή</translation>
    </message>
    <message>
        <source>Fit the développée to the view (F)</source>
        <translation>Προσαρμογή του αναπτύγματος στην προβολή (F)</translation>
    </message>
    <message>
        <source>Compute</source>
        <translation>Υπολογισμός</translation>
    </message>
    <message>
        <source>Compute the développée of the selected fragment in the background</source>
        <translation>Υπολογισμός στο παρασκήνιο του αναπτύγματος του επιλεγμένου θραύσματος</translation>
    </message>
    <message>
        <source>No développée yet: select a fragment and press Compute.</source>
        <translation>Δεν υπάρχει ακόμη ανάπτυγμα: επιλέξτε ένα θραύσμα και πατήστε Υπολογισμός.</translation>
    </message>
    <message>
        <source>Computing the développée of %1…</source>
        <translation>Υπολογισμός του αναπτύγματος του %1…</translation>
    </message>
    <message>
        <source>Select a fragment to compute its développée.</source>
        <translation>Επιλέξτε ένα θραύσμα για να υπολογίσετε το ανάπτυγμά του.</translation>
    </message>
    <message>
        <source>Press Compute for the développée of %1.</source>
        <translation>Πατήστε Υπολογισμός για το ανάπτυγμα του %1.</translation>
    </message>
    <message>
        <source>Horizon directions</source>
        <translation>Κατευθύνσεις ορίζοντα</translation>
    </message>
    <message>
        <source>Skydome shading of the développée: how many azimuths each pixel searches for its horizon (more is smoother and slower). Not the 3D view&apos;s skydome.</source>
        <translation>Σκίαση θόλου ουρανού του ξετυλίγματος: πόσα αζιμούθια ερευνά κάθε εικονοστοιχείο για τον ορίζοντά του (περισσότερα: ομαλότερο και πιο αργό). Όχι ο θόλος ουρανού της τρισδιάστατης όψης.</translation>
    </message>
    <message>
        <source>noise %1 mm smoothed by %2 mm</source>
        <translation>θόρυβος %1 mm, εξομάλυνση %2 mm</translation>
    </message>
    <message>
        <source>noise %1 mm, raw heights</source>
        <translation>θόρυβος %1 mm, ακατέργαστα ύψη</translation>
    </message>
    <message>
        <source>Smooth noise</source>
        <translation>Εξομάλυνση θορύβου</translation>
    </message>
    <message>
        <source>Skydome: smooth the scanner&apos;s noise out of the heights before the horizon search, so that flat, open surfaces read evenly instead of as salt and pepper. Off: the raw heights.</source>
        <translation>Θόλος ουρανού: εξομάλυνση του θορύβου του σαρωτή στα ύψη πριν από την αναζήτηση του ορίζοντα, ώστε οι επίπεδες, ανοιχτές επιφάνειες να διαβάζονται ομοιόμορφα αντί για «αλάτι και πιπέρι». Ανενεργό: τα ακατέργαστα ύψη.</translation>
    </message>
    <message>
        <source>Width (Gaussian σ) of the smoothing; Automatic sets it from the noise measured on the heights. The status line says what was used.</source>
        <translation>Πλάτος (σ της γκαουσιανής) της εξομάλυνσης· το Αυτόματο το ορίζει από τον θόρυβο που μετρήθηκε στα ύψη. Η γραμμή κατάστασης λέει ποιο χρησιμοποιήθηκε.</translation>
    </message>
    <message>
        <source>; </source>
        <comment>between the parts of a status line</comment>
        <translation> · </translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeSettings</name>
    <message>
        <source>the number of directions must be between %1 and %2</source>
        <translation>το πλήθος των διευθύνσεων πρέπει να είναι μεταξύ %1 και %2</translation>
    </message>
    <message>
        <source>the pixel size must be a positive length, or 0 for automatic</source>
        <translation>το μέγεθος εικονοστοιχείου πρέπει να είναι θετικό μήκος ή 0 για αυτόματο</translation>
    </message>
    <message>
        <source>the light elevation must be between 0° and 90°</source>
        <translation>η γωνία ύψους του φωτός πρέπει να είναι μεταξύ 0° και 90°</translation>
    </message>
    <message>
        <source>the axis needs a finite point and a non-zero direction</source>
        <translation>ο άξονας χρειάζεται ένα πεπερασμένο σημείο και μια μη μηδενική διεύθυνση</translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation>Κύλινδρος</translation>
    </message>
    <message>
        <source>Cone</source>
        <translation>Κώνος</translation>
    </message>
    <message>
        <source>Surface of revolution</source>
        <translation>Επιφάνεια εκ περιστροφής</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Ύψος</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Φως</translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation>Θόλος ουρανού</translation>
    </message>
    <message>
        <source>the unrolling radius must be a positive length</source>
        <translation>η ακτίνα ξετυλίγματος πρέπει να είναι θετικό μήκος</translation>
    </message>
    <message>
        <source>the smoothing must be a positive length, or 0 for automatic</source>
        <translation>η εξομάλυνση πρέπει να είναι θετικό μήκος, ή 0 για αυτόματη</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DeveloppeeView</name>
    <message>
        <source>No développée yet: select a fragment and press Compute.</source>
        <translation>Δεν υπάρχει ακόμη ανάπτυγμα: επιλέξτε ένα θραύσμα και πατήστε Υπολογισμός.</translation>
    </message>
    <message>
        <source>u %1 mm   v %2 mm   (no data)</source>
        <translation>u %1 mm   v %2 mm   (χωρίς δεδομένα)</translation>
    </message>
    <message>
        <source>u %1 mm   v %2 mm   h %3 mm</source>
        <translation>u %1 mm   v %2 mm   h %3 mm</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DockJob</name>
    <message>
        <source>Dock %1 to the flutes</source>
        <translation>Πρόσδεση του %1 στις ραβδώσεις</translation>
    </message>
    <message>
        <source>Could not dock %1: %2.</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: %2.</translation>
    </message>
    <message>
        <source>θ</source>
        <translation>θ</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>r</source>
        <translation>r</translation>
    </message>
    <message>
        <source>tangent</source>
        <translation>εφαπτομενικά</translation>
    </message>
    <message>
        <source>lean</source>
        <translation>κλίση</translation>
    </message>
    <message>
        <source>roll</source>
        <translation>περιστροφή</translation>
    </message>
    <message>
        <source>%1 ±%2°</source>
        <translation>%1 ±%2°</translation>
    </message>
    <message>
        <source>%1 ±%2 mm</source>
        <translation>%1 ±%2 mm</translation>
    </message>
    <message>
        <source>Docked %1: RMS %2 mm over %3 points, moved %4 flutes about the axis, %5 s</source>
        <translation>Προσδέθηκε το %1: RMS %2 mm σε %3 σημεία, μετακινήθηκε %4 ραβδώσεις γύρω από τον άξονα, %5 s</translation>
    </message>
    <message>
        <source>uncertainty %1</source>
        <translation>αβεβαιότητα %1</translation>
    </message>
    <message>
        <source>not fixed by the flutes, left as it was: %1</source>
        <translation>δεν καθορίζεται από τις ραβδώσεις, έμεινε ως είχε: %1</translation>
    </message>
    <message>
        <source>; </source>
        <comment>between the parts of a status line</comment>
        <translation> · </translation>
    </message>
    <message>
        <source>Could not dock %1: its %2 points are too few (at least 200 are needed).</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: τα %2 σημεία του είναι πολύ λίγα (χρειάζονται τουλάχιστον 200).</translation>
    </message>
    <message>
        <source>Could not dock %1: it is too far from the drum; %2 of its points lie within %3 mm of the drum&apos;s surface (at least 200 are needed). Bring it nearer its place on the drum (the Move tool, or its placement in the drum frame in Properties) and dock again.</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: είναι πολύ μακριά από τον σπόνδυλο· %2 από τα σημεία του βρίσκονται εντός %3 mm από την επιφάνεια του σπονδύλου (χρειάζονται τουλάχιστον 200). Φέρτε το πιο κοντά στη θέση του στον σπόνδυλο (το Εργαλείο Μετακίνησης, ή η θέση του στο σύστημα του σπονδύλου στις Ιδιότητες) και κάντε ξανά πρόσδεση.</translation>
    </message>
    <message>
        <source>Could not dock %1: from where it stands its outer face does not meet the drum&apos;s surface. Bring it nearer its place on the drum and dock again.</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: από τη θέση όπου βρίσκεται, η εξωτερική του όψη δεν συναντά την επιφάνεια του σπονδύλου. Φέρτε το πιο κοντά στη θέση του στον σπόνδυλο και κάντε ξανά πρόσδεση.</translation>
    </message>
    <message>
        <source>Could not dock %1: no flutes can be read on its outer face (flute signal %2, at least %3 needed). Lock θ (Tools › Docking locks) to dock it against the drum&apos;s surface alone.</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: δεν διαβάζονται ραβδώσεις στην εξωτερική του όψη (σήμα ραβδώσεων %2, απαιτείται τουλάχιστον %3). Κλειδώστε το θ (Εργαλεία › Κλειδώματα πρόσδεσης) για πρόσδεση μόνο στην επιφάνεια του σπονδύλου.</translation>
    </message>
    <message>
        <source>Could not dock %1: fewer than 200 of its points stayed on the flutes. Start it nearer its place and dock again.</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: λιγότερα από 200 σημεία του έμειναν στις ραβδώσεις. Ξεκινήστε πιο κοντά στη θέση του και κάντε ξανά πρόσδεση.</translation>
    </message>
    <message>
        <source>Could not dock %1: the registration did not settle in %2 iterations.</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: η ευθυγράμμιση δεν σταθεροποιήθηκε σε %2 επαναλήψεις.</translation>
    </message>
    <message>
        <source>%1 times the drum&apos;s own RMS: it may rest on the wrong flute or be held off its place by a lock</source>
        <translation>%1 φορές η RMS του ίδιου του σπονδύλου: ίσως κάθεται σε λάθος ράβδωση ή ένα κλείδωμα το κρατά μακριά από τη θέση του</translation>
    </message>
    <message>
        <source>Could not dock %1: the registration did not settle in %2 iterations. θ is locked and may hold it off its flute: unlock θ (Tools › Docking locks), or bring it onto its flute first.</source>
        <translation>Δεν ήταν δυνατή η πρόσδεση του %1: η ευθυγράμμιση δεν σταθεροποιήθηκε σε %2 επαναλήψεις. Το θ είναι κλειδωμένο και ίσως το κρατά μακριά από τη ράβδωσή του: ξεκλειδώστε το θ (Εργαλεία › Κλειδώματα πρόσδεσης) ή φέρτε το πρώτα στη ράβδωσή του.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DockRunner</name>
    <message>
        <source>The docking drum changed while its guides were fitted</source>
        <translation>Ο σπόνδυλος πρόσδεσης άλλαξε κατά την προσαρμογή των οδηγών του</translation>
    </message>
    <message>
        <source>%1 or the drum moved while it was docked: the dock was not applied</source>
        <translation>Το %1 ή ο σπόνδυλος μετακινήθηκε κατά την πρόσδεση: η πρόσδεση δεν εφαρμόστηκε</translation>
    </message>
    <message>
        <source>Dock %1</source>
        <translation>Πρόσδεση του %1</translation>
    </message>
    <message>
        <source>Docking %1 was cancelled</source>
        <translation>Η πρόσδεση του %1 ακυρώθηκε</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::DrumFramePoseWidget</name>
    <message>
        <source>θ about the axis:</source>
        <translation>θ γύρω από τον άξονα:</translation>
    </message>
    <message>
        <source>z along the axis:</source>
        <translation>z κατά μήκος του άξονα:</translation>
    </message>
    <message>
        <source>r from the axis:</source>
        <translation>r από τον άξονα:</translation>
    </message>
    <message>
        <source>Lean:</source>
        <translation>Κλίση:</translation>
    </message>
    <message>
        <source>Roll:</source>
        <translation>Περιστροφή:</translation>
    </message>
    <message>
        <source>Azimuth of the fragment&apos;s centre about the drum axis, from the drum&apos;s reference direction (as in its développée); typing turns the fragment about the axis</source>
        <translation>Αζιμούθιο του κέντρου του θραύσματος γύρω από τον άξονα του σπονδύλου, από τη διεύθυνση αναφοράς του σπονδύλου (όπως στο ανάπτυγμά του)· η πληκτρολόγηση περιστρέφει το θραύσμα γύρω από τον άξονα</translation>
    </message>
    <message>
        <source>Height of the fragment&apos;s centre along the drum axis, from the axis guide&apos;s point</source>
        <translation>Ύψος του κέντρου του θραύσματος κατά μήκος του άξονα του σπονδύλου, από το σημείο του οδηγού άξονα</translation>
    </message>
    <message>
        <source>Distance of the fragment&apos;s centre from the drum axis</source>
        <translation>Απόσταση του κέντρου του θραύσματος από τον άξονα του σπονδύλου</translation>
    </message>
    <message>
        <source>Turn about the tangent through the fragment&apos;s centre (leans it in or out)</source>
        <translation>Περιστροφή γύρω από την εφαπτομένη που περνά από το κέντρο του θραύσματος (το γέρνει προς τα μέσα ή έξω)</translation>
    </message>
    <message>
        <source>Turn about the radial direction through the fragment&apos;s centre (turns its flutes sideways)</source>
        <translation>Περιστροφή γύρω από την ακτινική διεύθυνση που περνά από το κέντρο του θραύσματος (στρέφει τις ραβδώσεις του πλάγια)</translation>
    </message>
    <message>
        <source>This fragment has no drum with an axis guide (put it in an assembly with a drum, or Tools › Dock against this drum), or its octree is not open yet.</source>
        <translation>Αυτό το θραύσμα δεν έχει σπόνδυλο με οδηγό άξονα (βάλτε το σε συναρμολόγηση με σπόνδυλο, ή Εργαλεία › Πρόσδεση σε αυτόν τον σπόνδυλο), ή το οκταδικό του δέντρο δεν έχει ανοίξει ακόμη.</translation>
    </message>
    <message>
        <source>No fragment selected.</source>
        <translation>Δεν έχει επιλεγεί θραύσμα.</translation>
    </message>
    <message>
        <source>In the frame of %1:</source>
        <translation>Στο σύστημα του %1:</translation>
    </message>
    <message>
        <source>Spin:</source>
        <translation>Ιδιοπεριστροφή:</translation>
    </message>
    <message>
        <source>Turn about the line through the fragment&apos;s centre parallel to the axis; with θ and the tilts it fixes the orientation. The tilts and the spin are measured from the fragment&apos;s frame as scanned</source>
        <translation>Περιστροφή γύρω από την ευθεία που περνά από το κέντρο του θραύσματος παράλληλα στον άξονα· μαζί με το θ και τις κλίσεις ορίζει τον προσανατολισμό. Οι κλίσεις και η ιδιοπεριστροφή μετρώνται από το σύστημα του θραύσματος όπως σαρώθηκε</translation>
    </message>
    <message>
        <source>This is the drum the others are placed against: select one of them.</source>
        <translation>Αυτός είναι ο σπόνδυλος ως προς τον οποίο τοποθετούνται τα άλλα: επιλέξτε ένα από αυτά.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::EditAxisDialog</name>
    <message>
        <source>Edit axis</source>
        <translation>Επεξεργασία άξονα</translation>
    </message>
    <message>
        <source>The axis guide in the fragment&apos;s own frame: a point on it and its direction.</source>
        <translation>Ο οδηγός άξονα στο σύστημα του ίδιου του θραύσματος: ένα σημείο του και η κατεύθυνσή του.</translation>
    </message>
    <message>
        <source>Point (x, y, z):</source>
        <translation>Σημείο (x, y, z):</translation>
    </message>
    <message>
        <source>Direction (x, y, z):</source>
        <translation>Κατεύθυνση (x, y, z):</translation>
    </message>
    <message>
        <source>The direction of the axis cannot be zero: give at least one non-zero component (for a vertical axis: 0, 0, 1).</source>
        <translation>Η κατεύθυνση του άξονα δεν μπορεί να είναι μηδενική: δώστε τουλάχιστον μία μη μηδενική συνιστώσα (για κατακόρυφο άξονα: 0, 0, 1).</translation>
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
        <source>these data and settings do not allow it</source>
        <translation>αυτά τα δεδομένα και οι ρυθμίσεις δεν το επιτρέπουν</translation>
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
    <name>stylos::widgets::FragmentPropertiesWidget</name>
    <message>
        <source>Name</source>
        <translation>Όνομα</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Ορατό</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Χρώμα</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>Rotation X</source>
        <translation>Περιστροφή X</translation>
    </message>
    <message>
        <source>Rotation Y</source>
        <translation>Περιστροφή Y</translation>
    </message>
    <message>
        <source>Rotation Z</source>
        <translation>Περιστροφή Z</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Σημεία</translation>
    </message>
    <message>
        <source>Leaf cells</source>
        <translation>Κελιά-φύλλα</translation>
    </message>
    <message>
        <source>Total cells</source>
        <translation>Σύνολο κελιών</translation>
    </message>
    <message>
        <source>Depth</source>
        <translation>Βάθος</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Αρχείο</translation>
    </message>
    <message>
        <source>Shown in the 3D view</source>
        <translation>Εμφανίζεται στην τρισδιάστατη προβολή</translation>
    </message>
    <message>
        <source>Choose the fragment&apos;s display colour</source>
        <translation>Επιλογή του χρώματος εμφάνισης του θραύσματος</translation>
    </message>
    <message>
        <source>Translation along the scene&apos;s x axis, in metres</source>
        <translation>Μετατόπιση κατά μήκος του άξονα x της σκηνής, σε μέτρα</translation>
    </message>
    <message>
        <source>Rotation about the x axis, applied first, in degrees</source>
        <translation>Περιστροφή γύρω από τον άξονα x, εφαρμόζεται πρώτη, σε μοίρες</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>δεν βρέθηκε</translation>
    </message>
    <message>
        <source>opening…</source>
        <translation>άνοιγμα…</translation>
    </message>
    <message>
        <source>Fragment colour</source>
        <translation>Χρώμα θραύσματος</translation>
    </message>
    <message>
        <source>Imported as</source>
        <translation>Εισήχθη ως</translation>
    </message>
    <message>
        <source>%1 up, in %2</source>
        <translation>%1 προς τα πάνω, σε %2</translation>
    </message>
    <message>
        <source>offset %1, %2, %3</source>
        <translation>μετατόπιση %1, %2, %3</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Διαστάσεις</translation>
    </message>
    <message>
        <source>Extent of the fragment&apos;s leaf cells along its own x, y and z axes (its scan&apos;s frame, z up), whatever its pose</source>
        <translation>Έκταση των φύλλων του θραύσματος κατά μήκος των δικών του αξόνων x, y και z (το σύστημα της σάρωσής του, z προς τα πάνω), όποια κι αν είναι η θέση του</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GizmoReadout</name>
    <message>
        <source>Along the fragment&apos;s X: %1 mm</source>
        <translation>Κατά τον X του θραύσματος: %1 mm</translation>
    </message>
    <message>
        <source>Along X: %1 mm</source>
        <translation>Κατά X: %1 mm</translation>
    </message>
    <message>
        <source>Along the fragment&apos;s Y: %1 mm</source>
        <translation>Κατά τον Y του θραύσματος: %1 mm</translation>
    </message>
    <message>
        <source>Along Y: %1 mm</source>
        <translation>Κατά Y: %1 mm</translation>
    </message>
    <message>
        <source>Along the fragment&apos;s Z: %1 mm</source>
        <translation>Κατά τον Z του θραύσματος: %1 mm</translation>
    </message>
    <message>
        <source>Along Z: %1 mm</source>
        <translation>Κατά Z: %1 mm</translation>
    </message>
    <message>
        <source>About the fragment&apos;s X: %1°</source>
        <translation>Γύρω από τον X του θραύσματος: %1°</translation>
    </message>
    <message>
        <source>About X: %1°</source>
        <translation>Γύρω από τον X: %1°</translation>
    </message>
    <message>
        <source>About the fragment&apos;s Y: %1°</source>
        <translation>Γύρω από τον Y του θραύσματος: %1°</translation>
    </message>
    <message>
        <source>About Y: %1°</source>
        <translation>Γύρω από τον Y: %1°</translation>
    </message>
    <message>
        <source>About the fragment&apos;s Z: %1°</source>
        <translation>Γύρω από τον Z του θραύσματος: %1°</translation>
    </message>
    <message>
        <source>About Z: %1°</source>
        <translation>Γύρω από τον Z: %1°</translation>
    </message>
    <message>
        <source>Along the drum axis: %1 mm</source>
        <translation>Κατά τον άξονα του σπονδύλου: %1 mm</translation>
    </message>
    <message>
        <source>Radially: %1 mm</source>
        <translation>Ακτινικά: %1 mm</translation>
    </message>
    <message>
        <source>Tilt about the radial direction: %1°</source>
        <translation>Κλίση γύρω από την ακτινική διεύθυνση: %1°</translation>
    </message>
    <message>
        <source>Tilt about the tangent: %1°</source>
        <translation>Κλίση γύρω από την εφαπτομένη: %1°</translation>
    </message>
    <message numerus="yes">
        <source>About the drum axis: %1° (%n flute(s))</source>
        <translation>
            <numerusform>Γύρω από τον άξονα του σπονδύλου: %1° (%n ράβδωση)</numerusform>
            <numerusform>Γύρω από τον άξονα του σπονδύλου: %1° (%n ραβδώσεις)</numerusform>
        </translation>
    </message>
    <message>
        <source>About the drum axis: %1°</source>
        <translation>Γύρω από τον άξονα του σπονδύλου: %1°</translation>
    </message>
    <message>
        <source>%1 · Esc cancels</source>
        <translation>%1 · Esc ακυρώνει</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GuideFitJob</name>
    <message>
        <source>Drum guides of %1</source>
        <translation>Οδηγοί σπονδύλου του %1</translation>
    </message>
    <message>
        <source>Could not fit the guides of %1: %2.</source>
        <translation>Δεν ήταν δυνατή η προσαρμογή των οδηγών του %1: %2.</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Άξονας</translation>
    </message>
    <message>
        <source>Flute %1</source>
        <translation>Ράβδωση %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::GuideFitRunner</name>
    <message>
        <source>Delete the guides of %1</source>
        <translation>Διαγραφή των οδηγών του %1</translation>
    </message>
    <message>
        <source>Fit the guides of %1</source>
        <translation>Προσαρμογή των οδηγών του %1</translation>
    </message>
    <message>
        <source>Fitting the guides of %1 was cancelled</source>
        <translation>Η προσαρμογή των οδηγών του %1 ακυρώθηκε</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ImportOptionsDialog</name>
    <message>
        <source>Import options</source>
        <translation>Επιλογές εισαγωγής</translation>
    </message>
    <message>
        <source>Stylos works with Z up and in metres. Say how the scans are stored: their points are turned and scaled once, as their octrees are built, and the project remembers it.</source>
        <translation>Το Stylos δουλεύει με τον άξονα Z προς τα πάνω και σε μέτρα. Δηλώστε πώς είναι αποθηκευμένες οι σαρώσεις: τα σημεία τους περιστρέφονται και κλιμακώνονται μία φορά, κατά την κατασκευή των οκταδικών δέντρων τους, και το έργο το θυμάται.</translation>
    </message>
    <message>
        <source>&amp;Up axis of the scans:</source>
        <translation>&amp;Κατακόρυφος άξονας των σαρώσεων:</translation>
    </message>
    <message>
        <source>&amp;Unit of the scans:</source>
        <translation>&amp;Μονάδα των σαρώσεων:</translation>
    </message>
    <message>
        <source>+Z (already upright)</source>
        <translation>+Z (ήδη όρθιες)</translation>
    </message>
    <message>
        <source>−Z (upside down)</source>
        <translation>−Z (ανάποδα)</translation>
    </message>
    <message>
        <source>+Y (Y up)</source>
        <translation>+Y (Y προς τα πάνω)</translation>
    </message>
    <message>
        <source>−Y (Y down)</source>
        <translation>−Y (Y προς τα κάτω)</translation>
    </message>
    <message>
        <source>+X (X up)</source>
        <translation>+X (X προς τα πάνω)</translation>
    </message>
    <message>
        <source>−X (X down)</source>
        <translation>−X (X προς τα κάτω)</translation>
    </message>
    <message>
        <source>metres (m)</source>
        <translation>μέτρα (m)</translation>
    </message>
    <message>
        <source>centimetres (cm)</source>
        <translation>εκατοστά (cm)</translation>
    </message>
    <message>
        <source>millimetres (mm)</source>
        <translation>χιλιοστά (mm)</translation>
    </message>
    <message>
        <source>&amp;Offset (site coordinates, in that unit):</source>
        <translation>&amp;Μετατόπιση (συντεταγμένες θέσης, σε αυτή τη μονάδα):</translation>
    </message>
    <message>
        <source>Subtracted from every x, before the turn and the scaling</source>
        <translation>Αφαιρείται από κάθε x, πριν από την περιστροφή και την κλιμάκωση</translation>
    </message>
    <message>
        <source>Subtracted from every y, before the turn and the scaling</source>
        <translation>Αφαιρείται από κάθε y, πριν από την περιστροφή και την κλιμάκωση</translation>
    </message>
    <message>
        <source>Subtracted from every z, before the turn and the scaling</source>
        <translation>Αφαιρείται από κάθε z, πριν από την περιστροφή και την κλιμάκωση</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::LegendText</name>
    <message>
        <source>preserved marble</source>
        <translation>σωζόμενο μάρμαρο</translation>
    </message>
    <message>
        <source>fractured marble</source>
        <translation>θραυσμένο μάρμαρο</translation>
    </message>
    <message>
        <source>plaster/restoration</source>
        <translation>γύψος/αποκατάσταση</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>άγνωστο</translation>
    </message>
    <message>
        <source>point</source>
        <translation>βελόνι</translation>
    </message>
    <message>
        <source>flat chisel</source>
        <translation>ίσια σμίλη</translation>
    </message>
    <message>
        <source>claw chisel</source>
        <translation>οδοντωτή σμίλη</translation>
    </message>
    <message>
        <source>drill</source>
        <translation>τρυπάνι</translation>
    </message>
    <message>
        <source>rasp</source>
        <translation>ράσπα</translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation>Υλικό / κατάσταση</translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation>Ίχνη εργαλείων</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Καμία</translation>
    </message>
    <message>
        <source>Diagonal</source>
        <translation>Διαγώνια</translation>
    </message>
    <message>
        <source>Back diagonal</source>
        <translation>Αντίστροφη διαγώνια</translation>
    </message>
    <message>
        <source>Cross</source>
        <translation>Σταυρωτή</translation>
    </message>
    <message>
        <source>Diagonal cross</source>
        <translation>Διαγώνια σταυρωτή</translation>
    </message>
    <message>
        <source>Dots</source>
        <translation>Κουκκίδες</translation>
    </message>
    <message>
        <source>Horizontal</source>
        <translation>Οριζόντια</translation>
    </message>
    <message>
        <source>Vertical</source>
        <translation>Κατακόρυφη</translation>
    </message>
    <message>
        <source>Solid</source>
        <translation>Συμπαγής</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::LegendWidget</name>
    <message>
        <source>Colour of “%1”</source>
        <translation>Χρώμα της «%1»</translation>
    </message>
    <message>
        <source>Rename class “%1” to “%2”</source>
        <translation>Μετονομασία της κλάσης «%1» σε «%2»</translation>
    </message>
    <message>
        <source>Recolour class “%1”</source>
        <translation>Αλλαγή χρώματος της κλάσης «%1»</translation>
    </message>
    <message>
        <source>Change the hatch of “%1”</source>
        <translation>Αλλαγή της διαγράμμισης της «%1»</translation>
    </message>
    <message>
        <source>class %1</source>
        <translation>κλάση %1</translation>
    </message>
    <message>
        <source>Add class “%1”</source>
        <translation>Προσθήκη της κλάσης «%1»</translation>
    </message>
    <message>
        <source>Delete class “%1”</source>
        <translation>Διαγραφή της κλάσης «%1»</translation>
    </message>
    <message numerus="yes">
        <source>%n cell(s) hold this class. What becomes of them?</source>
        <translation>
            <numerusform>%Ln κελί έχει αυτή την κλάση. Τι θα γίνει;</numerusform>
            <numerusform>%Ln κελιά έχουν αυτή την κλάση. Τι θα γίνουν;</numerusform>
        </translation>
    </message>
    <message>
        <source>Unlabel them</source>
        <translation>Να μείνουν χωρίς κλάση</translation>
    </message>
    <message>
        <source>Move them to</source>
        <translation>Να μεταφερθούν στην</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Διαγραφή</translation>
    </message>
    <message>
        <source>The black-and-white pattern of this class on plates</source>
        <translation>Το ασπρόμαυρο μοτίβο αυτής της κλάσης στους πίνακες</translation>
    </message>
    <message>
        <source>Being measured…</source>
        <translation>Μετράται…</translation>
    </message>
    <message>
        <source>Surface area on the object, m²</source>
        <translation>Εμβαδόν επιφάνειας πάνω στο αντικείμενο, m²</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>Κλάση</translation>
    </message>
    <message>
        <source>Hatch</source>
        <translation>Διαγράμμιση</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Κελιά</translation>
    </message>
    <message>
        <source>Area (m²)</source>
        <translation>Εμβαδόν (m²)</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Προσθήκη</translation>
    </message>
    <message>
        <source>Add a class to the layer of the selected row</source>
        <translation>Προσθήκη κλάσης στο στρώμα της επιλεγμένης γραμμής</translation>
    </message>
    <message>
        <source>Colour…</source>
        <translation>Χρώμα…</translation>
    </message>
    <message>
        <source>Change the colour of the selected class</source>
        <translation>Αλλαγή του χρώματος της επιλεγμένης κλάσης</translation>
    </message>
    <message>
        <source>Delete…</source>
        <translation>Διαγραφή…</translation>
    </message>
    <message>
        <source>Delete the selected class (its cells are unlabelled or moved to another class)</source>
        <translation>Διαγραφή της επιλεγμένης κλάσης (τα κελιά της μένουν χωρίς κλάση ή μεταφέρονται σε άλλη)</translation>
    </message>
    <message>
        <source>Click a class to paint it; double-click its name to rename it</source>
        <translation>Κλικ σε μια κλάση για να τη βάψετε· διπλό κλικ στο όνομά της για μετονομασία</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PaintToolBar</name>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>Pan</source>
        <translation>Μετακίνηση</translation>
    </message>
    <message>
        <source>Navigate: drag to pan, click to mark the point in 3D (N)</source>
        <translation>Πλοήγηση: σύρετε για μετακίνηση, κλικ για σήμανση του σημείου στο 3Δ (N)</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>Πινέλο</translation>
    </message>
    <message>
        <source>Paint the active class with a round brush (B)</source>
        <translation>Βάψιμο της ενεργής κλάσης με στρογγυλό πινέλο (B)</translation>
    </message>
    <message>
        <source>Eraser</source>
        <translation>Γόμα</translation>
    </message>
    <message>
        <source>Unlabel the cells under a round brush (E)</source>
        <translation>Αφαίρεση της κλάσης από τα κελιά κάτω από στρογγυλό πινέλο (E)</translation>
    </message>
    <message>
        <source>Polygon</source>
        <translation>Πολύγωνο</translation>
    </message>
    <message>
        <source>Fill a polygon with the active class: click its corners and double-click, or drag a lasso (L); Escape cancels</source>
        <translation>Γέμισμα πολυγώνου με την ενεργή κλάση: κλικ στις κορυφές του και διπλό κλικ, ή σύρετε ένα λάσο (L)· το Escape ακυρώνει</translation>
    </message>
    <message>
        <source>Wand</source>
        <translation>Ραβδί</translation>
    </message>
    <message>
        <source>Fill the connected pixels of similar height or shading with the active class (W)</source>
        <translation>Γέμισμα με την ενεργή κλάση των συνεχόμενων εικονοστοιχείων με παρόμοιο ύψος ή σκίαση (W)</translation>
    </message>
    <message>
        <source>Holes</source>
        <translation>Κενά</translation>
    </message>
    <message>
        <source>Fill the holes enclosed by the clicked region with its class (H)</source>
        <translation>Γέμισμα των κενών που περικλείει η περιοχή του κλικ με την κλάση της (H)</translation>
    </message>
    <message>
        <source>The annotation layer shown and painted</source>
        <translation>Το στρώμα σχολιασμού που εμφανίζεται και βάφεται</translation>
    </message>
    <message>
        <source>The class the brush, polygon and wand paint</source>
        <translation>Η κλάση που βάφουν το πινέλο, το πολύγωνο και το ραβδί</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Μέγεθος</translation>
    </message>
    <message>
        <source>Brush and eraser diameter on the object</source>
        <translation>Διάμετρος πινέλου και γόμας πάνω στο αντικείμενο</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Ύψος</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Σκίαση</translation>
    </message>
    <message>
        <source>What the magic wand compares</source>
        <translation>Τι συγκρίνει το μαγικό ραβδί</translation>
    </message>
    <message>
        <source>The magic wand takes pixels within this of the clicked one</source>
        <translation>Το μαγικό ραβδί παίρνει τα εικονοστοιχεία που απέχουν έως τόσο από αυτό του κλικ</translation>
    </message>
    <message>
        <source>Overlay</source>
        <translation>Επικάλυψη</translation>
    </message>
    <message>
        <source>Opacity of the annotation over the développée</source>
        <translation>Αδιαφάνεια του σχολιασμού πάνω στην ανάπτυξη</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PlateDialog</name>
    <message>
        <source>Développée</source>
        <translation>Ανάπτυγμα</translation>
    </message>
    <message>
        <source>Front</source>
        <translation>Πρόσοψη</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>Πίσω</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Αριστερά</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Δεξιά</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Κάτοψη</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>Από κάτω</translation>
    </message>
    <message>
        <source>Current view</source>
        <translation>Τρέχουσα όψη</translation>
    </message>
    <message>
        <source>Skydome</source>
        <translation>Θόλος ουρανού</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Φως</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Ύψος</translation>
    </message>
    <message>
        <source>Headlight</source>
        <translation>Μετωπικός φωτισμός</translation>
    </message>
    <message>
        <source>Page</source>
        <translation>Σελίδα</translation>
    </message>
    <message>
        <source>Margins</source>
        <translation>Περιθώρια</translation>
    </message>
    <message>
        <source>Resolution (dpi)</source>
        <translation>Ανάλυση (dpi)</translation>
    </message>
    <message>
        <source>Bits per sample (TIFF, PNG)</source>
        <translation>Bit ανά δείγμα (TIFF, PNG)</translation>
    </message>
    <message>
        <source>Template</source>
        <translation>Πρότυπο</translation>
    </message>
    <message>
        <source>Caption</source>
        <translation>Λεζάντα</translation>
    </message>
    <message>
        <source>Add panel</source>
        <translation>Προσθήκη πλαισίου</translation>
    </message>
    <message>
        <source>Remove panel</source>
        <translation>Αφαίρεση πλαισίου</translation>
    </message>
    <message>
        <source>Panels</source>
        <translation>Πλαίσια</translation>
    </message>
    <message>
        <source>Export plate</source>
        <translation>Εξαγωγή πίνακα</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Οριζόντια</translation>
    </message>
    <message>
        <source>Legend of the annotation classes</source>
        <translation>Υπόμνημα των κλάσεων σχολιασμού</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Εξαγωγή…</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Όψη</translation>
    </message>
    <message>
        <source>Scale 1:</source>
        <translation>Κλίμακα 1:</translation>
    </message>
    <message>
        <source>Shading</source>
        <translation>Σκίαση</translation>
    </message>
    <message>
        <source>Annotation</source>
        <translation>Σχολιασμός</translation>
    </message>
    <message>
        <source>Hatches</source>
        <translation>Διαγραμμίσεις</translation>
    </message>
    <message>
        <source>Fragment</source>
        <translation>Θραύσμα</translation>
    </message>
    <message>
        <source>Choose a template…</source>
        <translation>Επιλέξτε πρότυπο…</translation>
    </message>
    <message>
        <source>Développée and front view</source>
        <translation>Ανάπτυγμα και πρόσοψη</translation>
    </message>
    <message>
        <source>Front, right and top views</source>
        <translation>Πρόσοψη, δεξιά όψη και κάτοψη</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Κανένα</translation>
    </message>
    <message>
        <source>Material / condition</source>
        <translation>Υλικό / κατάσταση</translation>
    </message>
    <message>
        <source>Tool marks</source>
        <translation>Ίχνη εργαλείων</translation>
    </message>
    <message>
        <source>(all visible; the first for a développée)</source>
        <translation>(όλα τα ορατά· το πρώτο για ανάπτυγμα)</translation>
    </message>
    <message>
        <source>Drawing the preview…</source>
        <translation>Σχεδίαση της προεπισκόπησης…</translation>
    </message>
    <message>
        <source>Turned (%1 × %2 mm)</source>
        <translation>Περιστραμμένη (%1 × %2 mm)</translation>
    </message>
    <message>
        <source>A4 (210 × 297 mm)</source>
        <translation>A4 (210 × 297 mm)</translation>
    </message>
    <message>
        <source>A3 (297 × 420 mm)</source>
        <translation>A3 (297 × 420 mm)</translation>
    </message>
    <message>
        <source>US letter (215.9 × 279.4 mm)</source>
        <translation>Letter ΗΠΑ (215,9 × 279,4 mm)</translation>
    </message>
    <message>
        <source>Journal print area, 170 × 105 mm</source>
        <translation>Επιφάνεια εκτύπωσης περιοδικού, 170 × 105 mm</translation>
    </message>
    <message>
        <source>Journal print area, 205 × 135 mm</source>
        <translation>Επιφάνεια εκτύπωσης περιοδικού, 205 × 135 mm</translation>
    </message>
    <message>
        <source>%1 × %2 mm</source>
        <translation>%1 × %2 mm</translation>
    </message>
    <message>
        <source>Panel %1 (%2)</source>
        <translation>Το πλαίσιο %1 (%2)</translation>
    </message>
    <message>
        <source>The panel (%1)</source>
        <translation>Το πλαίσιο (%1)</translation>
    </message>
    <message>
        <source>%1 is %2; the print area is %3: use %4 or smaller, or a larger page.</source>
        <translation>%1 έχει διαστάσεις %2· η επιφάνεια εκτύπωσης είναι %3: επιλέξτε %4 ή μικρότερη κλίμακα, ή μεγαλύτερη σελίδα.</translation>
    </message>
    <message>
        <source>%1 is %2; the print area is %3: no scale fits this page, use a larger page.</source>
        <translation>%1 έχει διαστάσεις %2· η επιφάνεια εκτύπωσης είναι %3: καμία κλίμακα δεν χωρά σε αυτή τη σελίδα, επιλέξτε μεγαλύτερη σελίδα.</translation>
    </message>
    <message>
        <source>%1, placed at (%2, %3) mm, is %4 with its texts and leaves the %5 page.</source>
        <translation>%1, στη θέση x %2 mm, y %3 mm, έχει διαστάσεις %4 με τα κείμενά του και βγαίνει από τη σελίδα των %5.</translation>
    </message>
    <message>
        <source>The plate needs %1 mm of height; the print area is %2: use smaller scales, a larger page or the other orientation.</source>
        <translation>Ο πίνακας χρειάζεται ύψος %1 mm· η επιφάνεια εκτύπωσης είναι %2: επιλέξτε μικρότερες κλίμακες, μεγαλύτερη σελίδα ή τον άλλο προσανατολισμό.</translation>
    </message>
    <message>
        <source>The plate needs %1 mm of height; the print area is %2: use smaller scales (%3), a larger page or the other orientation.</source>
        <translation>Ο πίνακας χρειάζεται ύψος %1 mm· η επιφάνεια εκτύπωσης είναι %2: επιλέξτε μικρότερες κλίμακες (%3), μεγαλύτερη σελίδα ή τον άλλο προσανατολισμό.</translation>
    </message>
    <message>
        <source>The caption needs %1 mm of height on its own; the print area is %2: shorten the caption or use a larger page.</source>
        <translation>Η λεζάντα μόνη της χρειάζεται ύψος %1 mm· η επιφάνεια εκτύπωσης είναι %2: συντομεύστε τη λεζάντα ή επιλέξτε μεγαλύτερη σελίδα.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::PlateTexts</name>
    <message>
        <source>développée</source>
        <translation>ανάπτυγμα</translation>
    </message>
    <message>
        <source>front view</source>
        <translation>πρόσοψη</translation>
    </message>
    <message>
        <source>back view</source>
        <translation>πίσω όψη</translation>
    </message>
    <message>
        <source>left view</source>
        <translation>αριστερή όψη</translation>
    </message>
    <message>
        <source>right view</source>
        <translation>δεξιά όψη</translation>
    </message>
    <message>
        <source>top view</source>
        <translation>κάτοψη</translation>
    </message>
    <message>
        <source>bottom view</source>
        <translation>όψη από κάτω</translation>
    </message>
    <message>
        <source>orthographic view</source>
        <translation>ορθογραφική όψη</translation>
    </message>
    <message>
        <source>skydome</source>
        <translation>θόλος ουρανού</translation>
    </message>
    <message>
        <source>light</source>
        <translation>φως</translation>
    </message>
    <message>
        <source>height</source>
        <translation>ύψος</translation>
    </message>
    <message>
        <source>headlight</source>
        <translation>μετωπικός φωτισμός</translation>
    </message>
    <message>
        <source>axis</source>
        <translation>άξονας</translation>
    </message>
    <message>
        <source>.</source>
        <comment>the decimal point of the numbers on a plate</comment>
        <translation>,</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::RemoveFragmentCommand</name>
    <message>
        <source>Remove %1</source>
        <translation>Αφαίρεση %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::RenameFragmentCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>Μετονομασία %1 σε %2</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ScanImporter</name>
    <message>
        <source>Scans and octrees (%1)</source>
        <translation>Σαρώσεις και οκταδικά δέντρα (%1)</translation>
    </message>
    <message>
        <source>Packed octrees (*.poct)</source>
        <translation>Συμπαγή οκταδικά δέντρα (*.poct)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Όλα τα αρχεία (*)</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Εισαγωγή του %1</translation>
    </message>
    <message>
        <source>Could not import %1: %2.</source>
        <translation>Δεν ήταν δυνατή η εισαγωγή του %1: %2.</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Εισαγωγή %1</translation>
    </message>
    <message numerus="yes">
        <source>%1: %Ln point(s) with NaN or infinite coordinates skipped</source>
        <translation>
            <numerusform>%1: παραλείφθηκε %Ln σημείο με συντεταγμένες NaN ή άπειρες</numerusform>
            <numerusform>%1: παραλείφθηκαν %Ln σημεία με συντεταγμένες NaN ή άπειρες</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not import %1: the folder %2 cannot be created or written to.</source>
        <translation>Δεν ήταν δυνατή η εισαγωγή του %1: ο φάκελος %2 δεν μπορεί να δημιουργηθεί ή να δεχτεί εγγραφή.</translation>
    </message>
    <message numerus="yes">
        <source>%1 holds %Ln scan(s), merged into one fragment; each point&apos;s normal was estimated from its own scan&apos;s points</source>
        <translation>
            <numerusform>Το %1 περιέχει %Ln σάρωση, συγχωνευμένη σε ένα θραύσμα· το κάθετο διάνυσμα κάθε σημείου εκτιμήθηκε από τα σημεία της δικής του σάρωσης</numerusform>
            <numerusform>Το %1 περιέχει %Ln σαρώσεις, συγχωνευμένες σε ένα θραύσμα· το κάθετο διάνυσμα κάθε σημείου εκτιμήθηκε από τα σημεία της δικής του σάρωσης</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SceneDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Χωρίς τίτλο</translation>
    </message>
    <message>
        <source>The project has no file yet: choose one with Save as.</source>
        <translation>Το έργο δεν έχει ακόμη αρχείο: επιλέξτε ένα με την Αποθήκευση ως.</translation>
    </message>
    <message>
        <source>Could not save %1: %2.</source>
        <translation>Δεν ήταν δυνατή η αποθήκευση του %1: %2.</translation>
    </message>
    <message>
        <source>Opening %1</source>
        <translation>Άνοιγμα του %1</translation>
    </message>
    <message>
        <source>New assembly %1</source>
        <translation>Νέα συναρμολόγηση %1</translation>
    </message>
    <message>
        <source>Remove assembly %1</source>
        <translation>Διάλυση συναρμολόγησης %1</translation>
    </message>
    <message>
        <source>Rename %1</source>
        <translation>Μετονομασία %1</translation>
    </message>
    <message>
        <source>Take out of assembly</source>
        <translation>Αφαίρεση από τη συναρμολόγηση</translation>
    </message>
    <message>
        <source>Move into %1</source>
        <translation>Μετακίνηση στο %1</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>Μετακίνηση %1</translation>
    </message>
    <message>
        <source>Set the drum of %1</source>
        <translation>Ορισμός σπονδύλου του %1</translation>
    </message>
    <message>
        <source>Show %1</source>
        <translation>Εμφάνιση %1</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>Απόκρυψη %1</translation>
    </message>
    <message>
        <source>Change the legend</source>
        <translation>Αλλαγή του υπομνήματος</translation>
    </message>
    <message>
        <source>Remove the class %1</source>
        <translation>Αφαίρεση της κατηγορίας %1</translation>
    </message>
    <message>
        <source>Could not save the annotations of %1 into %2: %3.</source>
        <translation>Δεν ήταν δυνατή η αποθήκευση των σχολίων του %1 στο %2: %3.</translation>
    </message>
    <message>
        <source></source>
        <translation>Αφαίρεση της κλάσης %1</translation>
    </message>
    <message>
        <source>Keep the plate&apos;s settings</source>
        <translation>Διατήρηση των ρυθμίσεων του πίνακα</translation>
    </message>
    <message>
        <source>Could not copy the octrees into the project&apos;s folder: %1.</source>
        <translation>Δεν ήταν δυνατή η αντιγραφή των οκταδικών δέντρων στον φάκελο του έργου: %1.</translation>
    </message>
    <message>
        <source>The plate layout kept in %1 could not be read: the project opens without it, and its text stays in the file until a new plate is set (File › Export plate…).</source>
        <translation>Η διάταξη πίνακα που φυλάσσεται στο %1 δεν διαβάστηκε: το έργο ανοίγει χωρίς αυτήν, και το κείμενό της μένει στο αρχείο έως ότου οριστεί νέος πίνακας (Αρχείο › Εξαγωγή πίνακα…).</translation>
    </message>
    <message>
        <source>%1 holds keys this version of Stylos does not read; they are left out and will not be saved: %2</source>
        <translation>Το %1 περιέχει κλειδιά που αυτή η έκδοση του Stylos δεν διαβάζει· παραλείπονται και δεν θα αποθηκευτούν: %2</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SceneTreeModel</name>
    <message>
        <source>%1 (missing)</source>
        <translation>%1 (δεν βρέθηκε)</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Άξονας</translation>
    </message>
    <message>
        <source>Groove</source>
        <translation>Ράβδωση</translation>
    </message>
    <message>
        <source>Scene</source>
        <translation>Σκηνή</translation>
    </message>
    <message>
        <source>Développée (%1, %2 × %3)</source>
        <translation>Ανάπτυγμα (%1, %2 × %3)</translation>
    </message>
    <message numerus="yes">
        <source>Assembly of %n fragment(s)</source>
        <translation>
            <numerusform>Συναρμολόγηση %n θραύσματος</numerusform>
            <numerusform>Συναρμολόγηση %n θραυσμάτων</numerusform>
        </translation>
    </message>
    <message>
        <source>Docks against %1</source>
        <translation>Προσαρμόζεται στο %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentColourCommand</name>
    <message>
        <source>Change the colour of %1</source>
        <translation>Αλλαγή χρώματος %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentGuidesCommand</name>
    <message>
        <source>Change the guides of %1</source>
        <translation>Αλλαγή των οδηγών του %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentPoseCommand</name>
    <message>
        <source>Move %1</source>
        <translation>Μετακίνηση %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SetFragmentVisibleCommand</name>
    <message>
        <source>Show %1</source>
        <translation>Εμφάνιση %1</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>Απόκρυψη %1</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::SkydomeJob</name>
    <message>
        <source>Skydome of %1</source>
        <translation>Θόλος ουρανού του %1</translation>
    </message>
    <message>
        <source>Could not compute the skydome of %1: %2.</source>
        <translation>Δεν ήταν δυνατός ο υπολογισμός του θόλου ουρανού του %1: %2.</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::TaskListWidget</name>
    <message>
        <source>No background tasks</source>
        <translation>Καμία εργασία στο παρασκήνιο</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Ακύρωση</translation>
    </message>
    <message>
        <source>Stop this task</source>
        <translation>Διακοπή αυτής της εργασίας</translation>
    </message>
    <message>
        <source>Waiting…</source>
        <translation>Σε αναμονή…</translation>
    </message>
</context>
<context>
    <name>stylos::widgets::ViewportWidget</name>
    <message>
        <source>The 3D view needs OpenGL 3.3: %1</source>
        <translation>Η τρισδιάστατη προβολή απαιτεί OpenGL 3.3: %1</translation>
    </message>
</context>
</TS>
