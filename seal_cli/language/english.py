"""Closed-class English: the function words the tagger reads, listed once.

Determiners, numbers, pronouns, prepositions, particles, conjunctions, subordinators, politeness
formulae, words of address, titles, fillers, spellings of function words, the subjects and
finite verbs that mark a statement, time words. These are the language, not any corpus: an
open-class word (a noun, an adjective, a name) is never listed, and verbs come from the frame
library's lexical units (:mod:`seal_cli.language.lexicon`). Multiword entries ("as soon as", "could
you") are matched as phrases by the tagger.
"""

from __future__ import annotations

from collections.abc import Sequence


def _closed_class(*lines: str) -> frozenset[str]:
    return frozenset(" ".join(lines).split())


NEGATED_AUXILIARIES = {"is": "isn't", "are": "aren't", "was": "wasn't", "were": "weren't", "do": "don't",
                       "does": "doesn't", "did": "didn't", "have": "haven't", "has": "hasn't", "can": "can't",
                       "could": "couldn't", "would": "wouldn't", "will": "won't", "should": "shouldn't"}
"""An auxiliary or modal and its negative contraction."""
_INVERTED_SUBJECTS = frozenset(["you", "there", "we", "i", "it", "they", "anyone", "anybody", "someone", "somebody"])


def asked_negatively(phrases: frozenset[str]) -> frozenset[str]:
    """The phrases and, for each that opens a question with an auxiliary before its subject ("*is there* any",
    "*could you*", "*have we got*"), the same with the auxiliary negated ("*isn't there* any", "*couldn't you*",
    "*haven't we got*"). A negative yes/no question asks what the positive one asks (words25): "aren't there any
    clean spoons in the drawer?" is answered by looking for them, "can't you find the scissors?" asks for them to be
    found; the negation says what the speaker expected, not another thing to do."""
    more = set(phrases)
    for phrase in phrases:
        first, _, rest = phrase.partition(" ")
        if first in NEGATED_AUXILIARIES and rest.split()[:1] and rest.split()[0] in _INVERTED_SUBJECTS:
            more.add(f"{NEGATED_AUXILIARIES[first]} {rest}")
    return frozenset(more)


DETERMINERS = _closed_class("the a an some any this that these those each every all another both either no other such")
NUMBERS = {"zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
           "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "a couple of": 2, "a pair of": 2, "couple": 2,
           "several": 3, "few": 3, "many": 3}
POSSESSIVES = _closed_class("my your his her its our their")
NP_OPENERS = DETERMINERS | POSSESSIVES
"""Words that open a noun phrase: a determiner or a possessive ("*the* cup", "*my* keys"). A verb's form right
after one is a noun ("the *lights*", "my *drink*"); a noun phrase after a verb starts with one."""
DEMONSTRATIVES = frozenset(["this", "that", "these", "those"])
"""Demonstratives: a pronoun alone ("bring me *this*"), a determiner before a noun or "one" ("*this one*")."""
PRONOUNS = _closed_class("it them him her me you us they he she yourself myself himself herself themselves",
                         "itself ourselves yourselves something someone somebody everything everyone everybody",
                         "anything anyone anybody nothing one ones this that those these")
PERSON_PRONOUNS = _closed_class("him her me you us he she yourself myself himself herself themselves ourselves",
                                "yourselves someone somebody everyone everybody anyone anybody")
SOME_PERSON = _closed_class("someone somebody anyone anybody")
"""Pronouns that name any person ("find *someone* in the hall"): grounded as the class person, as "a person"."""
PREPOSITIONS = {
    "to": "to", "into": "into", "onto": "onto", "from": "from", "in": "in", "on": "on", "at": "at",
    "under": "under", "underneath": "under", "beneath": "under", "below": "under", "with": "with",
    "without": "without", "near": "near", "inside": "inside", "outside": "outside", "by": "by",
    "beside": "by", "behind": "behind", "above": "above", "over": "over", "across": "across",
    "through": "through", "toward": "to", "towards": "to", "around": "around", "between": "between",
    "among": "between", "upon": "on", "within": "in", "off": "off", "for": "for", "about": "about",
    "via": "via", "past": "past", "against": "against", "along": "along", "beyond": "beyond", "using": "with",
    "out of": "out of", "next to": "near", "close to": "near", "near to": "near",
    "closest to": "near", "nearest to": "near", "closer to": "near", "nearer to": "near", "in front of": "in front of",
    "on top of": "on", "inside of": "inside", "off of": "off", "away from": "from", "in between": "between",
    "on to": "onto", "in to": "into", "up to": "to", "down to": "to", "over to": "to", "out from": "from",
    "from inside": "from", "from within": "from", "from on top of": "from", "from under": "from",
    "from next to": "from", "from beside": "from", "from behind": "from", "from in front of": "from",
    "from near": "from", "to next to": "near", "to beside": "near",
    "back to": "to", "back into": "into", "back onto": "onto", "back in": "in", "back on": "on",
    "left of": "by", "right of": "by", "to the left of": "by", "to the right of": "by",
    "on the left of": "by", "on the right of": "by",
}
PARTICLES = _closed_class("up down out off away back over on in around about aside along")
REGIONS = _closed_class("top bottom front back middle centre center far near lower upper")
"""Words that say which region of a thing, before a side: "the *front* left of the stove", "the *lower* right of
the counter" (there "left of" is no preposition: the phrase is a region of the stove, as "the back of" is)."""
ORDINALS = _closed_class("first second third fourth fifth sixth last")
"""Ordinal words counting from an end of a row: "the *second* from the bottom shelf", "the third from the left drawer"
(:data:`~seal_cli.language.rules.function_words.ORDINAL_FROM_AN_END`)."""
ENDS = _closed_class("top bottom left right front back end door wall")
"""Where such a count starts: "the second from the *bottom* shelf", "the third drawer from the *left*"."""
SIDES = _closed_class("left right")
"""The sides of a thing, as regions: "the front *left* of the stove", "the *left* of the sink"."""
PREPOSITIONS.update({f"to {article}{region} {side} of": "by" for article in ("the ", "") for region in REGIONS
                     for side in SIDES} | {f"to {side} of": "by" for side in SIDES})
"""... and "to the bottom left of the sink" is where "to the left of" is: by it (so is "to left of", "to front
left of": the article left out)."""
WH_WORDS = _closed_class("what which who whom whose where when why how whether if")
FREE_RELATIVES = _closed_class("whoever whoever's whomever")
"""Pronouns that make a noun phrase of a clause about a person ("*whoever's* at the door, greet them"): said first and
taken up by "them", "him" or "her", such a phrase is set aside as a noun phrase is (``State.dislocated``). Not
"whatever": its phrase names a place or thing the pronoun "it" would take ("whatever's on the table": the table)."""
BE_WORDS = _closed_class("is are was were be am 's been being")
SEPARATOR_WORDS = frozenset(["and", "then", ",", ";", ":", "after that", "afterwards", "next", "finally",
                             "and then", "and after that", "after", "also", "once done", "when done",
                             "and finally", "before", "while", "or", "as well as", "plus", "followed by",
                             "as you", "while you", "so you can", "so that you can", "following that",
                             "after this", "after doing that", "having done that", "after you've done that",
                             "after you have done that", "once you've done that", "once you have done that",
                             "when you've done that", "when you have done that", "once that's done",
                             "once that is done", "after which", "following which"])
SEQUENCE_ADVERBS = frozenset(["later", "later on", "soon after", "soon afterwards", "shortly after",
                              "shortly afterwards", "after a while", "in a while", "a bit later", "a little later",
                              "from there"])
"""Adverbs of time that, between a joint and the next clause's verb, say only that it comes after ("meet Ana,
and *later on* find her in the garden"; "water the plants then *after a while* turn off the tap"): part of the
joint. Said after a verb's arguments they stay a time ("come back *later*", ``TIME_WORDS``). "*from there*" after a
joint goes on from the place just reached ("go to the kitchen and *from there* go to the office", words48: refused at
"there"); after a verb it is a source (``FROM_THERE``)."""
DEGREE_PHRASES = frozenset(["a little", "a little bit", "a bit", "a tad", "a touch", "a lot", "a crack", "a fraction",
                            "slightly", "somewhat", "fully", "halfway", "all the way"])
"""Noun phrases of degree (Quirk's downtoners and boosters): said after a verb's object ("open the curtains *a
crack*", "turn the heater up *a lot*") they say how far, no thing acted on; no frame element takes a degree, so the
parse keeps it as a remark beside the command (:mod:`~seal_cli.language.unplaced`), never drops it silently."""
AND_WORDS = frozenset(["and", "as well as", "plus"])
VERB_JOINTS = frozenset(["and", "then", ","])
"""Joints after which a bare word used mostly as a verb starts a clause of its own ("go to the kitchen *and* wait
there"; rule ``verb after a joint``)."""
ADDITIVES = frozenset(["too", "as well", "also"])
""""..., and the cereal *too*", "and the fork *as well*": a noun phrase with one of these ending its clause after a
separator is one more object of the clause before's verb, said again (a clause of its own), never a conjunct of
the phrase before it ("the kitchen table and the cereal")."""
"""Words that join like "and" (clauses or noun phrases)."""
DONE_BEFORE = frozenset(["before that", "but before that", "but first", "before doing that", "but before you do that",
                         "before you do that", "before you do so", "but before you do so", "prior to that"])
""""give me the cereal; *before that*, go to the table and find it", "bring me the cup, *but first* rinse it": a joint
after which the clauses are to be done before the clause said before it (words28); the clauses it joins with "and"
or a comma go with it. ``Clauses.order`` puts them first."""
YOU_MUST = frozenset(["you'll have to", "you'll need to", "you will have to", "you will need to", "you'd better",
                      "you had better"])
""""..., *you'll have to* go to the table and find it": what the robot must do, said to it (words28); a lead-in
(``POLITE``), and no statement a comma's remark drops (``State.statement_at``: "you'll" is a subject otherwise)."""
_ROBOT = ("the robot", "robot", "the robot's", "the robot 's", "robot's", "robot 's")
ROBOT_ADDRESSED = frozenset(
    [*(f"{robot} {must}" for robot in _ROBOT[:2] for must in ("should", "must", "needs to", "need to", "has to",
                                                             "have to", "will", "shall", "is to", "is going to",
                                                             "ought to", "is supposed to")),
     *(f"{whose} {aim} is to" for whose in ("the", "your", "our", *_ROBOT[2:])
       for aim in ("goal", "aim", "objective", "task", "job", "mission"))])
"""The robot told what to do in the third person, as people describe a task to it (alfred30): "*the robot should* put
the vase on the shelf", "*robot must* open the window", "*the goal is to* put the apple in the fridge", "*the
robot's task is to* bring the towel" say what "you should", "your task is to" say (a lead-in, ``POLITE``). The
robot described doing it ("the robot is cooking a potato", "the robot slices the bread") stays a statement."""
POLITE = asked_negatively(frozenset(["please", "kindly", "could you", "can you", "would you", "will you", "might you",
                                     "would you mind",
                    *(f"{modal} {anyone}" for modal in ("can", "could", "would", "will")   # "could someone bring ..."
                      for anyone in ("someone", "somebody", "anyone", "anybody")),
                    "could you please", "i want you to", "i need you to", "i would like you to",
                    "i want that you", "i need that you", "i would like that you",
                    "i'd like you to", "you should", "you must", "you need to", "you have to", "you will", *YOU_MUST,
                    "you can", "go ahead and", "robot", "hey", "ok", "okay", "now", "first", "firstly",
                    "just", "quickly", "quick", "carefully", "to", "try to", "attempt to", "then", "and", "also",
                    # words42: a hedge on the robot's ability before the verb, anywhere a clause starts ("once you're
                    # in the hall, *see if you can* find ...", "... and *try and* find ..."): the verb is the task
                    *(f"{see} {whether} you {can}" for see in ("see", "check") for whether in ("if", "whether")
                      for can in ("can", "could", "can manage to", "could manage to", "are able to")),
                    *(f"see {whether} you're able to" for whether in ("if", "whether")),
                    "try and", "try your best to", "do your best to",
                    # words42: a request asked as whether it is too much, a task announced with "next" or "first"
                    *(f"{be} {much} to ask you to" for be in ("would it be", "is it", "would that be")
                      for much in ("too much", "asking too much")),
                    *(f"{det} {task} is to" for det in ("your next", "the next", "your first", "the first")
                      for task in ("task", "job", "mission", "step")),
                    "go on and",
                    "simply",
                    "let's", "let 's", "be sure to", "make sure to", "remember to", "go and", "come and", "go", "come",
                    "would you be so kind as to", "would you be kind enough to", "be so kind as to",
                    "be kind enough to", "be good enough to", "be so good as to", "would you be so good as to",
                    "would you be good enough to", "could you be so kind as to", "do me a favor and",
                    "do me a favour and", "don't forget to", "do not forget to", "help me", "help me to", "help us",
                    "make sure you", "see that you", "hi", "hello", "hi there", "hello there", "hey there",
                    *(f"good {part}" for part in ("morning", "afternoon", "evening", "night", "day")),
                    "excuse me", "maybe", "perhaps", "oh", "ah",
                    "could i ask you to", "can i ask you to", "may i ask you to", "might i ask you to",
                    "could i trouble you to", "can i trouble you to", "may i trouble you to",
                    "might i trouble you to", "could i bother you to", "can i bother you to",
                    "ahh", "aw", "ugh", "urgh", "argh", "oops", "whoops", "sorry", "well", "gosh", "so",
                    "i'd appreciate it if you", "i would appreciate it if you", "i'd really appreciate it if you",
                    "i would really appreciate it if you", "i'd appreciate it if you could",
                    "i would appreciate it if you could", "i'd really appreciate it if you could",
                    "i would really appreciate it if you could", "i'd appreciate it if you would",
                    "i would appreciate it if you would", "would it be possible to", "would you be able to",
                    "could you be able to", "are you able to", "will you be able to", "would you be willing to",
                    "is it possible to", "is it possible for you to", "would it be possible for you to",
                    "your task is to", "your job is to", "the task is to", "your next task is to",
                    "i would like for you to", "i'd like for you to", "i want for you to", "i'll need you to",
                    "i will need you to", "we need you to", "we'll need you to", "wanna", "do you wanna",
                    "you wanna", "why don't you", "why not", "is possible to", "is possible for you to",
                    "hurry", "hurry up", "sorry to bother you", "sorry to trouble you", "sorry to disturb you",
                    "sorry to bother you but", "sorry to trouble you but", "sorry to disturb you but",
                    "do you mind", "how about", "what about", "how about you", "what about you",
                    # words43: a deed asked as a trouble ("*would it be too much trouble to* bring me a coffee?")
                    *(f"{would} {trouble}{whom} to" for would in ("would it be", "will it be", "is it")
                      for trouble in ("too much trouble", "any trouble", "a problem", "a bother", "too much to ask")
                      for whom in ("", " for you")),
                    # words43: leave to ask asked ("*mind if I ask you to* open the door?")
                    *(f"{lead}mind if i {ask} you to" for lead in ("", "do you ", "would you ", "would you really ")
                      for ask in ("ask", "asked", "could ask")),
                    # words49: a wish that someone did it ("*I wish someone would* close that window")
                    *(f"{wish} {who} would" for wish in ("i wish", "i really wish", "if only")
                      for who in ("you", "someone", "somebody", "anyone", "anybody")),
                    "i wish you'd", "if only you'd",
                    "second", "secondly", "third", "thirdly", "fourth",
                    "fourthly", "lastly", "listen",
                    *(f"{what} {who} {wish} you to do is" for what in ("what", "all") for who in ("i", "we")
                      for wish in ("want", "need", "'d like", "would like")),
                    *(f"{what} i'd like you to do is" for what in ("what", "all")),
                    "all i need is for you to", "all i want is for you to", "all we need is for you to",
                    "i'm asking you to", "i am asking you to", "i'm telling you to", "i am telling you to",
                    *(f"{here} what i {wish}" for here in ("here's", "here 's", "here is")
                      for wish in ("need", "want", "need you to do", "want you to do")),
                    "here's the task", "here 's the task",
                    "the task is", "your task is", "the job is", "your job is", "your mission is to",
                    "your mission is", "the plan is", "the plan is to",
                    # words35: the task announced with "for you to" or with what the robot must do
                    *(f"{what} {wish} is for you to" for what in ("what", "all")
                      for wish in ("i need", "i want", "i'd like", "i would like", "we need", "we want", "we'd like",
                                   "we would like")),
                    *(f"what {must} do is" for must in ("you have to", "you need to", "you should", "you must",
                                                         "you got to", "you've got to", "you have got to",
                                                         "you'll have to", "you will have to", "you're going to",
                                                         "you are going to")),
                    "here's the deal", "here 's the deal", "here is the deal", "here's the thing",
                    "here 's the thing", "here is the thing",
                    # words35: discourse markers said first, and the robot's ability asked
                    "alright", "all right", "right", "right so", "ok so", "okay so", "alright so", "so basically",
                    "basically", "listen up", "quick one", "a quick one", "first off", "first things first",
                    "first of all", "to start", "to start with", "to begin", "to begin with",
                    *(f"{modal} you manage to" for modal in ("can", "could", "will", "would")),
                    *(f"{be} you capable of" for be in ("are", "would", "would you be")),
                    *(f"do you think {able}" for able in ("you can", "you could", "you are able to",
                                                          "you're able to", "you would be able to",
                                                          "you'd be able to", "you could manage to")),
                    "you're going to", "you are going to", "you'll", "you'll need to", "you'll have to",
                    "you got to", "you've got to", "you have got to", "you need", "going to need you to",
                    "i'm going to need you to", "i am going to need you to", "we're going to need you to",
                    "i'd appreciate if you", "i would appreciate if you", "i'd appreciate if you could",
                    "let's have you", "let 's have you", "let's get you to", "let 's get you to",
                    "kind of", "kinda", "got to", "your going to", "your job", "your task", "your mission",
                    *ROBOT_ADDRESSED]))
POLITE_FORMULAE = frozenset([
    "when you get a chance", "when you get the chance", "when you have a chance", "when you get a moment",
    "when you have a moment", "when you have a minute", "when you have a second", "when you have time",
    "when you have a sec", "when you can", "whenever you can", "whenever you get a chance",
    "whenever you have a moment", "whenever you have time", "as soon as you can", "if you get a chance",
    "if you have a chance", "if you have a moment", "if you have a minute", "if you have a second",
    "if you have time", "if you can", "if possible", "if you please", "if you would", "if you don't mind",
    "if you do not mind", "if it's not too much trouble", "if it is not too much trouble", "if you wouldn't mind",
    "if you would not mind", "at your convenience", "when convenient", "when it's convenient", "no rush",
    "no hurry", "many thanks", "do me a favor", "do me a favour",
    "quick favor", "quick favour", "a quick favor", "a quick favour", "small favor", "small favour",
    "thanks a lot", "thanks so much", "thank you so much", "thanks very much", "thank you very much"])
AS_ABLE = frozenset(["possible", "you can", "you could", "you're able", "you are able", "you can manage",
                     "you're able to", "you are able to", "you can do it"])
"""What ends "as fast *as you can*", "as gently *as possible*" (``politeness.AS_ABLE_RULE``): the manner said at the
most the robot can; with a quantity between ("as much as you can") it is no manner but a thing."""
AS_ABLE_NOT_MANNER = frozenset(["much", "many", "few", "little", "far"])
"""Words between "as" and "as" that measure a thing or a way, not a manner ("bring *as many as* you can")."""
"""Politeness said as a clause of its own ("*when you get a chance*, could you ..."; "... *if you don't
mind*"): the robot's time is asked for, not a condition or a task. Only a whole clause: "if you can"
followed by more of its clause ("if you can reach the shelf, ...") is a condition. Thanks said first ("*thanks in
advance*: please ...") and a favour announced ("*quick favour* - grab me ...", "*do me a favour*: ...") are such
clauses too (words33; and ``THANKS_AHEAD``); "a quick question" is not (a question is what "ask" and "answer" take)."""
THANKS_AHEAD = ("thanks in advance", "thank you in advance")
"""Thanks said before the request is done ("*thanks in advance*: please ..."), a formula as ``POLITE_FORMULAE``'s
(words33). A tuple, not one of this module's tables of closed classes: ``scripts/build_lexical_units.py`` reads
every word of those tables as a closed-class word no WordNet verb may be, and "advance" is an open word (Go's
"advance", from WordNet, stays)."""
SPELLINGS = {"pls": "please", "plz": "please", "pleeease": "please", "thx": "thanks", "thanx": "thanks",
             "u": "you", "r": "are", "ya": "you", "ur": "your", "n": "and", "im": "i'm", "ive": "i've",
             "youre": "you're",
             "theyre": "they're", "thats": "that's", "dont": "don't", "doesnt": "doesn't", "didnt": "didn't",
             "isnt": "isn't", "arent": "aren't", "wasnt": "wasn't", "havent": "haven't", "couldnt": "couldn't",
             "wouldnt": "wouldn't", "shouldnt": "shouldn't", "shes": "she's", "hes": "he's", "whats": "what's",
             "theres": "there's", "wont": "won't", "cant": "can't", "wheres": "where's", "hows": "how's",
             "ill": "i'll", "id": "i'd", "youll": "you'll", "weve": "we've", "theyve": "they've", "itll": "it'll",
             "frm": "from", "thru": "through", "abt": "about", "cud": "could", "cld": "could", "wud": "would",
             "shud": "should", "pleez": "please", "ppl": "people", "wats": "what's", "wat's": "what's", "wat": "what",
             "urself": "yourself", "yrself": "yourself"}
"""Texting spellings of function words ("turn the lights off *pls*", "open it *n* wipe it", "where *r* my keys",
"tell her *im* late"): read as the word they spell."""
READ_AS_ONE = {"prior to": "before", "subsequent to": "after"}
"""Two words that say one preposition or subordinator, read as that word wherever they stand (alfred30): "pick up the
mug *prior to* turning on the lamp", "*prior to* that, open the door", "*subsequent to* washing it, put the cup
away" read as "before" and "after" do. One word of both spans (its text both words said)."""
RUN_TOGETHER = {"gimme": ("give", "me", "gim"), "lemme": ("let", "me", "lem"), "gonna": ("going", "to", "gon"),
              "gotta": ("got", "to", "got"), "outta": ("out", "of", "out"), "hafta": ("have", "to", "haf")}
"""Two words run together as they are said ("*gimme* the orange", "*lemme* know", "you *gotta* greet him"): each is
read as its two words (the first, the second, and the letters the first is written with; words35)."""
SEEN_QUESTIONS = frozenset(["see", "you see", "do you see", "you spot", "do you spot", "notice",
                            "you notice", "do you notice"])
"""A question of perception said before the command ("*see* the man by the window? greet him", "*do you see* the
cup on the shelf? bring it here"): whether the robot sees it asks nothing; it introduces what the command's
pronoun stands for, as a statement does. ("Can you see X?" is politeness and Guide's "see"; "did you notice X?"
is a search asked, ``SEEN_ASKED``; "spot X?" is Find's "spot".)"""
TAG_QUESTIONS = frozenset(["would you", "could you", "will you", "can you", "won't you", "wouldn't you",
                           "would you please", "will you please", "could you please"])
""""fetch me a spoon from the cabinet *would you*": a modal and "you" ending the request, with or without a
comma before it, ask nothing more (the politeness of a tag question)."""
ASKED_AGAIN = frozenset(["tell me", "tell us", "let me know", "let us know", "know", "any idea", "you know",
                         "tell me please", "please tell me"])
""""Which drink is the heaviest, *can you tell me*?", "who's at the door, *do you know*?": after a question and
its comma, the question asked again (a modal and "you" first, or not) and nothing after it asks nothing more."""
VOCATIVES = frozenset(["dear", "dearie", "love", "darling", "sweetheart", "sweetie", "honey", "hun", "pet", "mate",
                       "buddy", "pal", "sir", "madam", "ma'am", "miss", "robot", "friend", "my dear", "my friend",
                       "my love", "old friend", "thanks", "thank you", "please", "would you", "could you",
                       "will you", "can you", "won't you", "wouldn't you", "would you please", "will you please",
                       "could you please", "ok", "okay", "right", "yeah", "sorry", "ugh", "oh", "oops"])
"""Words of address and tags said after a request ("close the door, *dear*", "..., *would you*?",
"pass me the salt, *love*, ..."): no part of the clause."""
TITLES = frozenset(["mr", "mrs", "ms", "mx", "miss", "dr", "prof", "st", "rev", "revd", "fr", "sr", "capt", "sgt",
                    "lt", "col", "gen", "hon", "mme", "mlle", "messrs"])
"""Titles written as abbreviations before a name ("*Mr.* Patel", "*Dr.* Ahmed", "*St.* Mary's"): their full
stop ends no sentence, it is part of the word ("Mr."), and title and name are one name ("Mr. Patel")."""
TITLES_ONLY = frozenset(["mr", "mrs", "ms", "mx", "dr", "prof", "mme", "mlle", "messrs"])
"""The titles that are no other word of English, so a title even in lower case ("take *mr* smith to the kitchen");
"miss", "st" (street), "col" are words too, a title only when written capitalised."""
FILLERS = frozenset(["um", "umm", "ummm", "uh", "uhh", "uhm", "er", "erm", "ehm", "hmm", "hm", "mm", "mmm"])
"""Hesitations ("and then, *um*, chill the juice"): no word of the command; dropped, with a comma after them."""
FINITE = frozenset(["is", "are", "was", "were", "am", "'s", "has", "have", "had", "do", "does", "did", "can", "could",
                    "will", "would", "shall", "should", "must", "might", "may", "can't", "cannot", "couldn't",
                    "won't", "wouldn't", "shouldn't", "mustn't", "don't", "doesn't", "didn't", "isn't", "aren't",
                    "wasn't", "weren't", "hasn't", "haven't", "hadn't", "ain't", "keeps", "needs", "wants"])
"""Finite verbs that make a statement of what starts with a subject ("the bus *is* late", "she *can't*
sleep"): auxiliaries, modals, "be" and "have"."""
SUBJECTS = frozenset(["i", "he", "she", "we", "they", "it", "this", "that", "there", "these", "those", "everyone",
                      "everybody", "someone", "somebody", "nobody", "nothing", "everything"])
"""Pronouns that may start a statement said beside the command ("*it's* cold in here")."""
CONTRACTED = frozenset(["'s", "'re", "'m", "'ll", "'ve", "'d"])
STATEMENT_LINKS = frozenset(["or", "otherwise", "because", "cause", "cos", "coz", "cuz", "since", "as", "so", "but"])
"""Conjunctions before a statement after the request ("..., *or* it will melt", "..., *because* I'm cold")."""
BECAUSE = frozenset(["because", "cause", "'cause", "cos", "coz", "cuz", "'cos"])
FREQUENCY_ADVERBS = frozenset(["just", "still", "only", "even", "also", "often", "sometimes", "now", "again", "ever"])
"""Adverbs before a finite verb that -ly does not mark ("the timer *just* went")."""
THIRD_PERSON_SUBJECTS = frozenset(["he", "she", "it", "someone", "somebody", "everyone", "everybody", "nobody",
                                   "nothing", "everything"])
"""Subjects of a third-person verb: any inflected verb after them is finite ("he *likes* company")."""
LINKING_VERBS = frozenset(["seem", "appear", "look", "sound", "feel", "smell", "taste", "become", "remain"])
"""Linking verbs: their finite form makes a statement whatever follows ("the door *seems* loose")."""
SPEAKER_PRONOUNS = frozenset(["me", "us"])
"""Who speaks, as an object: going "with *me*" somewhere, the speaker leads."""
OBJECT_PRONOUNS = frozenset(["it", "them", "him", "her", "me", "us", "this", "that"])
BASE_FORM_SUBJECTS = frozenset(["i", "we", "they"])
"""Subjects whose verb has its base form ("we *open* at six"): after them, any verb is finite."""
END_MARKS = frozenset(".!?")
HERE_WORDS = frozenset(["here", "there", "over here", "over there", "upstairs", "downstairs", "indoors", "outdoors",
                        "nearby", "elsewhere", "everywhere", "somewhere", "anywhere", "in there", "in here"])
"""Words that name a place by themselves (deictic and directional adverbs): "come *here*", "bring it
*upstairs*". "in there" and "in here" are read as "there" and "here" ("count the cans *in there*": the
place named before)."""
LOCATIVE = ("in", "on", "at", "near", "under", "by", "inside", "behind", "above", "over", "in front of",
            "between", "around", "across", "through", "along", "beyond", "against", "outside", "past")
"""Prepositions (canonical forms) that say where something is ("*on* the sofa"): the roles they may name are
in ``roles.PREPOSITION_ROLES``."""
LOCATED = ("in", "on", "at", "inside")
"""Of those, the ones that say what place a thing is in ("standing *in* the corridor", "that's *on* the sofa"):
where to seek it or take it from ("next to the sink" is near a place, not in it)."""
BESIDE = ("near", "by", "behind", "in front of", "under")
"""Of those, the ones that put a thing beside another, not on or in it ("next to the remote", "under the
pillow", "in front of the phone"): what holds it is where the other thing is ("... *on the sofa*")."""
DIRECTIONS = frozenset(["upstairs", "downstairs", "indoors", "outdoors", "home"])
"""Place words that say where a motion goes ("carry the box *upstairs*", "go *outside*"): a goal, or where
something is looked for ("find the cat *downstairs*"), never where it is taken from (that is "from upstairs")."""
TIME_WORDS = frozenset(["now", "later", "soon", "today", "tonight", "tomorrow", "again", "too", "first",
                        "right away", "right now", "at once", "as well", "as soon as possible", "asap", "meanwhile",
                        "in a minute", "in a moment", "for now", "this morning", "this evening", "tonight",
                        "at the moment", "just now"])
"""Time adverbials said after a verb's arguments ("put it in the fridge *right away*"): they say when,
not what, and are no part of a noun phrase."""
PARTS_OF_DAY = frozenset(["morning", "afternoon", "evening", "night", "weekend"])
"""Parts of the day a time word names with "this", "tomorrow" or "tonight" before it ("*this afternoon*
close the blinds", "*tomorrow morning*, wake me up")."""
FREQUENCY_LEADS = frozenset(["every", "each"])
"""Determiners of a time said as how often ("*every morning*, open the curtains", "*each* evening"): with a part
of the day or a measure of time after them (``PARTS_OF_DAY``, ``TIME_UNITS``)."""
TIMES_SAID = frozenset(["once", "twice", "thrice"])
"""Adverbs of how many times ("*twice* a day"); a number before "times" says the same ("three times a week")."""
RATE_WORDS = frozenset(["a", "an", "per", "every", "each"])
"""Words between a number of times and its unit ("twice *a* day", "three times *per* week")."""
TIME_FIRST_LEAD = frozenset(["after", "before", "until", "till", "by"])
"""Prepositions of a time said first with a bare noun ("*after lunch* clean the counter", "*before bed*, turn off
the lights"): a time, no subordinate clause (no subject, no verb)."""
SUBORDINATORS = frozenset(["after", "before", "when", "whenever", "once", "as soon as", "until", "till", "if",
                           "unless", "as long as", "in case", "while"])
"""Words that start a subordinate clause: one of the robot's own ("*after you* wash them": a frame,
ordered) or a condition on the world ("*when* the water boils": no frame, the frame's
``condition``)."""
FIRST_LATER = frozenset(["after", "when", "whenever", "once", "as soon as"])
"""Subordinators whose clause is done before the main one ("put them away *after you* wash them")."""
TIME_UNITS = frozenset(["second", "seconds", "minute", "minutes", "hour", "hours", "moment", "moments", "while",
                        "day", "days", "week", "weeks"])
"""Measures of time: "for *three minutes*", "every *few minutes*" say how long or how often."""
TIME_ASKED = (frozenset(["when", "whenever", "if", "once"]), frozenset(["get", "have", "find", "got", "had", "found"]),
              frozenset(["a", "an", "the", "some", "any", "spare", "free", "quick", "little", "few"]),
              TIME_UNITS | frozenset(["chance", "opportunity", "sec", "secs", "min", "mins", "tick", "time"]))
"""The robot's time asked for in a clause of the robot's own: "*when you get a sec*", "*if you have a spare
minute*", "*once you find the time*": a subordinator, "you", a verb of having, a few words of quantity, a
measure of time or a chance. Politeness like ``POLITE_FORMULAE``, not a condition (and no Pick of "a sec")."""
MODALS = frozenset(["can", "could", "will", "would", "shall", "should", "may", "might", "must"])
"""The modal verbs: in a question one goes before the subject ("she *can* come": "*can* you come?")."""
NOMINATIVE = frozenset(["i", "he", "she", "we", "they"])
"""Subject pronouns: never an object, so after a noun one starts a clause ("the book *I* left on the sofa")."""
RELATIVES = frozenset(["that", "which", "who", "whom", "whose"])
HOLDING_VERBS = frozenset(["have", "hold", "contain"])
"""Verbs that say what a thing holds: "the box *that has* a candle in it" is the box with a candle in it."""
STATES_DONE = frozenset(["done", "finished", "ready", "there", "here", "back", "through"])
"""What "once you are ___" says of the robot when it only sequences: "*once you're done*, ..." is "then"."""
CLOCK_PREPOSITIONS = frozenset(["at", "by", "until", "till", "around", "in", "before"])
"""Prepositions of a time said with a number ("at three", "by 5 pm", "in ten minutes")."""
CLOCK_WORDS = frozenset(["am", "pm", "a.m.", "p.m.", "o'clock", "oclock", "sharp", "thirty", "fifteen",
                          "fortyfive", "twenty", "forty", "fifty"])
TIME_MEASURE = frozenset(["a", "an", "few", "couple", "of", "several", "another", "other", "more", "little", "short",
                           "good", "long"])
"""Words between "for"/"every" and a unit of time ("for *a little* while", "every *few* minutes")."""
NOT_PLACES = frozenset(["for", "with", "until", "till", "about"])
"""Prepositions that say no place: after "and" and a verb's base form ("and *wait for* me") they begin the
verb's complement, not where a list of things goes ("a bowl and pen *on* the desk")."""
PATH_PREPOSITIONS = frozenset(["to", "into", "onto", "from", "out of", "off", "through", "via", "past", "across",
                               "along"])
"""Prepositions of a path: "down from the shelf *and over to* my chair" goes on one path."""
PARTITIVES = frozenset(["some", "any", "all", "both", "each", "more", "enough", "half"])
"""Determiners that stand alone for a part of what was named ("pour *some* into the cup")."""
VAGUE_NUMBERS = frozenset(["one", "couple", "several", "few", "many"])
"""Number words that count but never label ("the red *one*", "a *few*")."""
QUANTIFIERS = frozenset(["one", "two", "three", "four", "both", "all", "some", "each", "any", "none", "most",
                          "either", "neither", "several", "many", "few"])

# ---------------------------------------------------------------------------------------------
# Constructions that say a request without its verb, and what each means as a plain command
# (the paraphrase's verb must be a lexical unit of the library, or the construction is not read)

QUESTION_WORDS = frozenset(["what", "who", "which", "whose", "whom", "what's", "who's"])
"""Words that start a question the robot answers by saying something ("*What's* the biggest thing on the
shelf?", "*Who* is in the kitchen?"): a bare question means "tell me ..." (``QUESTION_MEANS``)."""
QUESTION_MEANS = "tell"
WHERE_QUESTIONS = asked_negatively(frozenset([
    "where is", "where are", "where 's", "where's", "where're", "where did", "where has", "where have", "where had",
    "is there", "are there", "is there any", "are there any", "do we have", "do we have any", "have we got",
    "have we got any", "do we still have", "do we still have any", "whereabouts is", "whereabouts are",
    "whereabouts 's", "whereabouts's", "where stays", "where stay", "where sits", "where sit", "where lies",
    "where lie", "where stands", "where stand", "where hangs", "where hang"]))
"""Questions about where a thing is, or whether there is one ("*where is* the cup?", "*is there* a cup in the
kitchen?", "*do we have any* eggs?", "*where did* the cat go?", "*where have* my keys gone?", "*whereabouts is* the
remote?": "whereabouts" asking where, as only before "is"/"are"; a learner's verb of position said for "is",
"*where stays* the remote?", "where sits my bag?", words27): they mean "find ..."
(``WHERE_MEANS``); an auxiliary before a subject pronoun is ``WHERE_DID``'s ("where did *I* leave ...")."""
WHERE_MEANS = "find"
WHERE_DID = (frozenset(["where", "whereabouts"]),
             frozenset(["did", "do", "does", "have", "has", "can", "could", "should", "would", "will", "might", "may"]),
             frozenset(["i", "you", "we", "they", "he", "she"]))
""""*Where did I leave* my glasses?", "*where do we keep* the batteries", "*where can I find* the sponge": where,
an auxiliary or a modal, a subject and any verb, then what to find."""
SEEN_ASKED = (frozenset(["have", "has", "did", "haven't", "hasn't", "didn't", "can", "could", "can't", "couldn't"]),
              frozenset(["you", "anyone", "anybody", "someone", "somebody"]),
              frozenset(["see", "notice", "spot", "find", "come across"]))
""""*Have you seen* my phone?", "*did you notice* the keys anywhere?", "*has anyone found* my glasses?": a
question whether the thing was seen (an auxiliary of the past, a subject, a verb of perceiving or finding) asks
to find it (``WHERE_MEANS``); asked negatively too ("*haven't you seen* my glasses?"), and whether it can be
seen ("*can you see* the cat anywhere?": where "can you" is no politeness before a verb of the library; "can you
see the guest out" stays Guide's), words25."""
PERCEIVING = frozenset(["see", "spot", "notice", "come across", "happen to see", "happen to spot"])
"""Verbs of perceiving a thing by chance: in a condition ("*if you spot* my wallet, hand it to me", "if you come
across my keys, ...") they say whether the thing is met, asking for no search (words38: a Find, or a Go to the keys
for "come across"); "when you find it" is the robot's own step, as before."""
LEFT_ASKED = (frozenset(["did", "have", "has", "didn't", "haven't", "hasn't"]),
              frozenset(["i", "you", "we", "he", "she", "they", "anyone", "anybody", "someone", "somebody"]),
              frozenset(["leave", "left"]))
""""*Did I leave* the stove on?", "*has someone left* the door open?": a question whether someone left a thing
in a state (an auxiliary, a subject, "leave") asks about the thing's state, as "is the stove on?" does: check
the thing (``STATE_MEANS``), the state kept."""
REQUESTS = frozenset(["i'd like", "i would like", "i should like", "i'd love", "i would love", "i'd like to have",
                      "i would like to have", "can i have", "could i have", "may i have", "can i get", "could i get",
                      "may i get", "might i have", "might i get", "can i please get", "could i please get",
                      "can i please have", "could i please have", "may i please have", "i need", "i want",
                      "i'll have", "i will have", "i'll take", "can we have", "could we have", "we need", "we'd like",
                      "i'll need", "i will need", "we'll need", "we will need", "i'm gonna need", "we're gonna need",
                      "i'm going to need", "we're going to need", "i could use", "i could really use", "we could use",
                      "we could really use", "i could do with", "i could really do with", "we could do with",
                      "i could just do with", "i'd really like", "i would really like", "i'd quite like",
                      "i'd really love", "i really need", "i just need", "need", "i am wanting", "i'm wanting",
                      "i am needing", "i'm needing", "we are needing", "we're needing", "i am in need of",
                      "i'm in need of", "we are in need of", "we're in need of",
                      *(f"{modal} i {bother} you for" for modal in ("could", "can", "may", "might")
                        for bother in ("trouble", "bother")),
                      "we'd love", "we would love", "i wouldn't mind", "i would not mind", "we wouldn't mind",
                      "we would not mind",
                      "i fancy", "i'd fancy", "i would fancy", "i quite fancy", "i'd quite fancy", "i really fancy",
                      *(f"{who} {really}appreciate" for who in ("i'd", "i would", "we'd", "we would")
                        for really in ("", "really ", "much ")),
                      *(f"{modal} {who} {adverb} {verb}" for modal in ("can", "could", "may") for who in ("i", "we")
                        for adverb in ("possibly", "just", "please just") for verb in ("have", "get")),
                      *(f"{chance} {wish}" for chance in ("any chance", "is there any chance", "is there a chance")
                        for wish in ("of", "i could have", "i can have", "i could get", "i can get", "we could have",
                                     "we can have")),
                      *(f"what {wish} is" for wish in ("i need", "i want", "i'd like", "i would like", "we need",
                                                       "we want", "we'd like", "we would like")),
                      # words49: a thing asked for as whether asking is too much ("*would it be too much to ask
                      # for* a sandwich"), as a deed is (POLITE's "would it be too much to ask you to")
                      *(f"{be} {much} to ask for" for be in ("would it be", "is it", "would that be")
                        for much in ("too much", "asking too much"))])
"""A request for a thing said as the speaker's wish ("*I'd like* the red mug", "*Can I have* the big plate",
"*I need* a pen", "*I could do with* a towel"): it means "bring me ..." (``REQUEST_MEANS``, with the speaker as
recipient). Asked as a trouble to the hearer, a thing after "for" ("*might I trouble you for* a glass of water",
words26), as politeness asks a deed after "to" ("could I trouble you to ..."). A wish said as not minding ("*I
wouldn't mind* a biscuit") or as a chance asked ("*any chance I could have* a cushion?", "*any chance of* a cup of
tea?") is one too, and so are "I fancy X", and "could I possibly have X" (words30), and "I'd (really) appreciate X"
(words47; "I'd appreciate it if you ..." is the polite frame's, read first)."""
APPROVAL = frozenset(["great", "nice", "good", "lovely", "wonderful", "helpful", "perfect", "fantastic", "amazing",
                      "awesome", "brilliant", "handy", "ideal"])
"""Adjectives of approval in a wish said impersonally ("it would be *great* to have ..."). English, not any corpus's."""
IMPERSONAL_WISHES = frozenset(f"{it} be {really}{adjective} to have" for it in ("it would", "it'd", "it will", "it'll")
                              for really in ("", "really ", "so ") for adjective in APPROVAL)
"""A wish for a thing said impersonally ("*it would be great to have* a blanket", "it'd be nice to have the lights
on"): a wish as "I'd like" is (words43: refused as a statement)."""
REQUESTS = REQUESTS | IMPERSONAL_WISHES
REQUEST_MEANS = "bring"
HELP_MEANS = "come"
""""*I need a hand*", "we could use some help in the garage": help wished for with no deed said is the robot coming to
whoever asks, or to the place said ("come to me", "come to the garage": a unit of Go in the standard library); they
will say what the help is for (words47: a Bring of "a hand")."""
WISHED_PLACED = frozenset([*(f"{who} {wish}" for who in ("i", "we") for wish in ("want", "would like")),
                           "i'd like", "we'd like",
                           *(f"{who} really {wish}" for who in ("i", "we") for wish in ("want", "need")),
                           *(f"{who}{would} really like" for who in ("i", "we") for would in ("'d", " would"))])
FOLLOW_ASKED = ("guide", frozenset(["ask", "tell", "get", "invite"]),
                frozenset([f"to {verb} {who}" for verb in ("follow", "come with", "go with", "walk with")
                           for who in ("you", "me", "us")]))
"""A person asked to follow the robot ("*ask* Anna *to follow you* to the kitchen", "tell the man in the hat to come
with you"): the robot leads them, the unit ``FOLLOW_ASKED[0]`` (words42: it was a Tell of "follow you to the
kitchen", nobody led). The verbs of asking, and what the person is asked."""
FOUND_STATED = frozenset(["you'll find", "you will find", "you can find", "you should find", "you'd find", "you'll see",
                          "you will see", "you'll spot", "you will spot"])
""""*You'll find* Axel by the bookshelf, lead him to the kitchen": where the hearer will come upon someone or something
is a statement of where they are, as "Axel is by the bookshelf" is, when a comma and a command follow it (words46:
it was a Find of Axel before the leading). "you'll find the keys in the drawer *and* bring them" stays two steps."""
HELPED_MOVING = ("guide", frozenset(["go", "get", "come", "walk", "move", "head", "return"]),
                 frozenset(["to", "into", "towards", "toward", "back", "there", "here", "upstairs", "downstairs",
                            "outside", "inside", "home"]))
"""A person helped to move somewhere ("*help* him *get* to the kitchen", "help Sam go back to his room", "help her get
there"): the robot leads them, the unit ``HELPED_MOVING[0]`` (words46: it was a Go of the robot, the person dropped).
The verbs of moving (lemmas), and the words of where that must follow them ("help her get dressed" is no leading)."""
WISHED_PLACES = frozenset(["on", "onto", "in", "into", "inside", "under"])
PLACE_MEANS = "put"
""""*I want* the mug *on* the shelf", "I'd like the books in the box": the speaker's wish for where a thing is,
a phrase and a preposition of place (canonical, ``PREPOSITIONS``) with its phrase ending the sentence, means
"put the mug on the shelf" (``PLACE_MEANS``); "I need the scissors *from* the drawer" stays a request."""
OBLIGED = frozenset(["goes", "go", "belongs", "belong", "needs to go", "need to go", "should go", "has to go",
                     "have to go", "must go", "ought to go", "can go", "needs to be", "need to be", "should be",
                     "has to be", "have to be", "must be", "ought to be", "needs to be put", "need to be put",
                     "should be put", "has to be put", "must be put", "should be left", "needs to be left",
                     "needs", "need", "wants", "want"])
""""The bowl *should go* in the dishwasher", "the milk *belongs* in the fridge", "the door *should be* closed": a
thing said to belong somewhere is putting it there (``PLACE_MEANS``, a preposition of ``WISHED_PLACES`` or
"to"), and one said to be in a state is the verb whose result the state is ("close"); one that *needs* a verb's
-ing form ("the cup needs *washing*") is that verb."""
KNOW_WISHES = frozenset(["i'd like to know", "i would like to know", "i want to know", "i wanna know", "i need to know",
                         "i'd love to know", "i would love to know", "do you know", "i wonder", "i'm wondering",
                         "i am wondering", "i was wondering", "i'm curious", "i'm curious about", "any idea",
                         "have you any idea", "do you have any idea", "got any idea", "would you know",
                         "do you happen to know"])
"""The speaker's wish to know, said where a command starts ("*I'd like to know* the heaviest object on the
shelf", "*do you know* how many cups are left"): it means "tell me ..." (``QUESTION_MEANS``)."""
WHERE_ASKERS = asked_negatively(frozenset(["tell me", "tell us", "show me", "show us", "remind me", "remind us",
                          "let me know", "let us know", "know", "did you see", "have you seen", "did you notice",
                          "have you noticed"])) | KNOW_WISHES
"""A question about the robot's knowledge of where a thing is ("*do you know* where the tea spoon is?", "*can
you tell me* where the keys are?", "*show me* where the remote is"): a request to find it and say where it is,
read as "where is ..." ("find ...", ``WHERE_MEANS``); the verb of being after the thing is dropped
(``WHERE_BE``). Said before "where" only; "do you know how many ..." stays a wish to know."""
WHERE_BE = frozenset(["is", "are", "'s", "was", "were", "went", "goes", "go", "gone", "got to", "has gone", "have gone",
                      "ended up", "has got to", "have got to", "might be", "could be", "would be", "can be"])
TOPICS = frozenset(["as for", "regarding", "concerning", "as regards", "with regard to", "with regards to",
                    "speaking of", "talking of", "talking about", "as to"])
"""Words that name what the sentence is about before it ("*as for* the person in the kitchen, what is she wearing?",
"*regarding* the cup on the table, bring it to me"): the phrase after them is said first, as a bare one is
(words41: they were refused as unknown verbs)."""
TOTALS = frozenset(["in total", "in all", "total", "all told", "altogether", "all together", "overall",
                    "in sum", "all in all"])
"""Words that say a count is of all the things ("how many people are in the office *in total*?"): a count counts
them all, so they add nothing to it (words41: "in total" was read as a place, "total" refused)."""
INFORMATION = frozenset(["name", "names", "pose", "poses", "gesture", "gestures", "gender", "genders"])
"""What the robot reports of a person, as the GPSR generator asks it ("tell me the *name* of the person at the
door": its ``persInfo`` are name, pose and gesture; 2018's templates ask the gender too): given or brought to
someone, such a word is told (words41)."""
NUMBER_OF = frozenset(["tell me the number of", "tell me the total number of", "what is the number of",
                       "what 's the number of", "what is the total number of", "what 's the total number of",
                       "what number of", "give me the number of", "tell me the count of", "report the number of",
                       "count the number of", "count the total number of", "find out the number of",
                       "check the number of", "figure out the number of", "work out the number of",
                       "give me a count of", "give me the count of", "get me a count of", "i want a count of",
                       "i need a count of", "i'd like a count of", "do a count of", "take a count of",
                       "give me a headcount of", "do a headcount of", "take a headcount of",
                       "what is the count of", "what 's the count of", "what is the total count of",
                       "what 's the total count of", "let me know the number of", "let us know the number of",
                       "report back the number of", "report the total number of"])
"""Asking for a count by its number ("*tell me the number of* toys on the desk", "*what number of* people
..."), or by a count asked for ("*give me a count of* the people in the lounge", "*do a headcount of* the guests":
words33): it means "tell me how many ..." (``NUMBER_MEANS``, a unit of counting when the library has it)."""
NUMBER_MEANS = "tell me how many"
BEING_AT = (frozenset(["once", "when", "as soon as", "after"]), frozenset(["you're", "you are", "you 're"]),
            frozenset(["in", "at", "inside", "by", "near", "next to", "beside", "into"]))
""""*Once you're in* the living room, find Peyton": the robot is to be there first, "go to the living room, then
..." (``BEING_MEANS``): a subordinator, "you're", a preposition of place, a phrase, then the clause."""
BEING_MEANS = "go"
HAVING_FIRST = (frozenset(["once", "when", "as soon as", "after"]), frozenset(["you have", "you've", "you 've"]))
""""*Once you have* the spoon, put it in the dishwasher": the robot is to hold the thing first, "get the spoon,
then ..." (``HAVING_MEANS``): a subordinator, "you have" (no participle after it), a phrase, then the clause."""
HAVING_MEANS = "get"
PATH_ALONE = frozenset(["to", "into", "onto"])
""""*To* the bathroom", "*back to* the kitchen, please": a command that is only where to go (the preposition's
canonical form, ``PREPOSITIONS``) is going there (``PATH_MEANS``)."""
PATH_MEANS = "go"
DEPARTURE_MEANS = "go"
""""Grab the cup and *leave*": a one-word unit that puts its object somewhere, said with no object and nothing after it
but "now" or "please", is the robot going away (words40; said in a subordinate clause it is the time of the
command, ``State._departure_end``): the library's unit of going."""
ASKED_ALONE = frozenset(["please"])
""""Milk from the fridge, *please*", "the remote, please": a noun phrase and "please" with no verb in the
sentence is a request for the thing, "bring me ..." (``REQUEST_MEANS``)."""
CHECK_WHETHER = (frozenset(["check", "see", "find out", "look and see", "go and see", "go and check", "go see",
                            "go check", "figure out", "work out", "determine", "discover"]),
                 frozenset(["if", "whether"]), frozenset(["there is", "there are", "there 's", "there's"]))
""""*See if* anyone is in the kitchen", "*check whether* there is milk in the fridge": the question whether
it is there, asked as "find ..." (``WHERE_MEANS``), as "is anyone in the kitchen?" is. The verbs of finding
out by reasoning ("*figure out* who is in the garage", "*work out* how many cups are left", "*determine* ...",
"*discover* ...": words33) ask as "find out" does."""
STATE_MEANS = "check"
""""*Is* the fridge *open*?", "check *whether* the door is *closed*": a yes/no question about a thing's state means
"check the fridge" (a unit of LookAt in the standard library), the state asked kept beside the frame."""
ENSURED = frozenset(["make sure", "make certain", "ensure", "be sure", "see to it", "check that", "double check that"])
""""*Make sure* the stove is off", "*ensure* the door is closed": the state asked for is what to bring about,
the verb whose result it is ("turn off": ``SWITCHED_MEANS``; "closed": "close", the verb of the participle,
when it is a lexical unit of the library); "that" may follow ("make sure *that* the lamp is on")."""
STATE_ASKERS = frozenset(["tell me", "let me know", "let us know", "do you know", "i'd like to know",
                          "i would like to know", "i want to know", "i wonder", "i was wondering", "find out",
                          "check", "see", "look and see", "go and see", "go and check", "go check", "go see",
                          "make sure", "check and see"])
"""What asks whether something holds, before "if"/"whether" ("*tell me* if the keys are on the table",
"*let me know* whether the stove is on", "*find out* if Tom is in the kitchen"): the question, not the verb
of saying, is the frame (Find of a place, LookAt of a state)."""
OBJECT_PARTICLES = frozenset(["off", "up", "down", "out"])
"""Particles a verb may take before its object that never say where a thing is ("dust *off* the shelf"; not "in":
"a pan with a knife and ladle *in* the sink" names a place, words36)."""
DEPARTING = frozenset(["out", "away", "off"])
"""Particles that make a verb of going a leaving ("before you go *out*", "when you head *off*"): with nothing after
them the going is the time of the command, no frame (words36)."""
STATE_PARTICLES = frozenset(["on", "off", "open", "shut"])
"""Words that end a question of state though lemminflect lists them as no adjective ("is the TV *on*?")."""
KEEPING = frozenset(["keep"])
""""*Keep* the door shut", "keep the heater switched on": a verb that holds a thing in a state, a unit of no frame,
said with a thing and a word of state ending the clause, is the verb whose result the state is, as "leave the door
open" is (rule ``a thing left in a state``): the robot brings the state about; it cannot watch over it."""
STATE_ADVERBS = frozenset(["still", "already", "yet", "now", "really", "currently", "properly", "all", "fully",
                           "completely", "not"])
"""Adverbs said before the state asked ("is the light *still* on?", "is the fridge *not* open?"), part of it."""
SWITCHED_MEANS = {"on": "turn on", "off": "turn off"}
""""*Lights off* in the hall", "the TV on, please": a thing and "on"/"off", no verb, is switching it so
("turn the lights off"): the particle's unit, when the library has it."""
OPERATING = {"running": "on", "going": "on"}
""""keep the fan *running*", "leave the dishwasher *going*": a machine in operation, which is a thing switched on
(WordNet's run.v.? "operate, function": "the engine is running"); the state is "on"'s (``SWITCHED_MEANS``), words49."""
FOUND_OUT = frozenset(["who", "what", "which", "whose", "what's", "who's"])
""""*find out who* is in the hall", "*check what* is in the fridge", "see who's at the door": a verb of checking
and a question word asks the question (``QUESTION_MEANS``): "tell me who is in the hall"."""
LET_KNOW = ("let", "know")
""""*let* me *know* ...", "*let* Amara *know* that ...": "tell me ...", "tell Amara that ..." (``QUESTION_MEANS``)."""

ROOM_WORDS = frozenset({"kitchen", "bathroom", "bedroom", "living_room", "dining_room", "family_room", "garage",
    "hall", "hallway", "corridor", "office", "study", "attic", "basement", "cellar", "laundry", "laundry_room",
    "utility_room", "garden", "balcony", "porch", "lounge", "den", "nursery", "playroom", "lobby", "entrance",
    "foyer", "staircase", "terrace", "patio", "yard", "backyard", "guest_room", "washroom", "restroom",
    "shower_room", "gym", "library", "toilet_room", "cloakroom", "conservatory", "sunroom", "workshop", "upstairs",
    "downstairs"})
"""English names of the rooms of a house (general knowledge, not any corpus): a phrase ending in
one, or in "room", names a room. Kept in English, not in the library's types, because a class a category
lists is known *not* to be in the others ("open the garage" must stay possible)."""


def is_room_word(words: Sequence[str]) -> bool:
    """Whether words call something a room: "room" last, or a room's name (:data:`ROOM_WORDS`)."""
    words = tuple(words)
    return bool(words) and (words[-1] == "room" or "_".join(words) in ROOM_WORDS or words[-1] in ROOM_WORDS
                            or "_".join(words[-2:]) in ROOM_WORDS)


ROUTE_NOUNS = frozenset({"way", "route", "path"})
"""Nouns naming the route to a place, not a thing: "show them *the way* to the kitchen" leads them there."""


VERB_TAKES = (NP_OPENERS | PRONOUNS | PARTICLES | END_MARKS | frozenset(["please"])
              | frozenset(w for w in HERE_WORDS if " " not in w) | frozenset(p for p in PREPOSITIONS if " " not in p))
"""One-word openers of what a verb takes after it: an object (a determiner, a possessive, a pronoun), "here" or
"there", "please", a preposition or a particle, or the end of the sentence ("and *wait there*", "and *fold it*")."""


PARTS = frozenset(["lid", "door", "handle", "seat", "tank", "cover", "basin"])
"""The portions that are parts a thing is made with ("the fridge *door*", "a spoon with a blue *handle*"):
a thing said "with" one is described, not given contents."""
PROHIBITIVES = frozenset(["don't", "dont", "do not", "never", "please don't", "please do not", "please never"])
"""What opens an imperative said negatively, a prohibition ("*don't* open the window", "*do not* go in the
bedroom", "*never* leave the door open"): the robot is asked not to do something, which is no frame of the
library. "don't forget to" is a reminder, a request to do it (``POLITE``)."""
NOT_FORGOTTEN = frozenset(["forget", "fail"])
""""don't *forget* ...", "don't *fail* to ...": a negated verb of omission asks for the deed (no prohibition)."""
CANCELLATIONS = frozenset(["never mind", "nevermind", "forget about", "don't bother with", "don't bother about",
                           "no need to", "there's no need to", "you don't need to", "you needn't",
                           "cancel", "forget", "ignore", "disregard"])
"""What takes back something asked or expected ("*never mind* the lamp, turn on the fan", "*no need to* wash it"),
and the verbs of taking back ("*cancel* that, bring me a cup", "*forget* what I said, go to the garage",
"*ignore* the dishes, ..."): the clause they open asks nothing."""
HALTS = frozenset(["stop", "halt"])
"""Verbs of halting: said with no object ("*stop*!", "*halt*, wait there") they ask the robot to stop what it
does, a cancellation (``CANCELLATIONS``); with one ("stop the music") they are the verb of a frame."""
CORRECTION_MARKS = frozenset(["no", "no wait", "wait", "no sorry", "sorry", "i mean", "sorry i mean",
                              "no i mean", "i meant", "sorry i meant", "or rather", "rather", "actually",
                              "no actually", "oops", "whoops", "correction", "make that", "no make that",
                              "scratch that"])
"""Words that correct the phrase just said ("bring the cup, *no*, the mug", "open the window, *sorry, I mean*
the door", "give Sam the book, *or rather* the magazine"); commas may come between them. The phrase after them
stands for the last phrase said before them."""
GREETINGS = frozenset(["hey", "hi", "hello", "ok", "okay", "yo", "oi", "oy", "hiya", "heya", "howdy"])
"""Words that greet or call someone ("*hey* Siri, ...", "*ok* robot ..."): a word after one of them, before the
command, is the name of whom is addressed, whatever else it may mean ("hey *google*, turn on the lights")."""
SPEECH_ACTS = GREETINGS | frozenset(["thank", "thanks", "cheers", "please", "good", "goodbye", "bye", "robot"])
"""Words of a greeting, thanks or address: a command of politeness alone that has one ("thank you", "good morning,
robot", "hello") asks nothing, refused at its start (words38), not as a verb missing at its end."""
URGENT = frozenset(["now", "right now", "quick", "quickly", "asap", "fast", "hurry", "immediately", "right away",
                    "pronto", "please", "pls", "thanks", "thank you", "straight away", "at once"])
"""Words that ask for haste or say please, said as a phrase of their own in a command of bare phrases ("keys. hallway.
*now*", "bathroom, *quick*"): what is wanted is in the other phrases (``rules.telegraphic``)."""
RELAYING = frozenset(["says", "said", "wants", "wanted", "asks", "asked", "told", "tells", "would like", "'d like"])
"""Verbs by which a person's request is passed on to the robot ("mum *says* you have to ...", "Anna *asked* you to
...", "dad *wants* you to ..."): the request that follows is the command; who made it is said beside it."""
RELAYED_OBLIGATION = frozenset(["have to", "must", "should", "need to", "ought to", "'ve got to", "have got to",
                                "are to", "to", "can", "could", "will", "may"])
"""What comes after "you" in a request passed on ("... says you *have to* turn off the telly", "... asked you *to*
bring her a towel"), before its verb."""
OF = "of"
"""The preposition of a part, a measure or a whole ("a slice *of* apple", "one *of* them"): read by its own rule
(``rules.function_words.OF``), not one of :data:`PREPOSITIONS`, which say where."""
FUNCTION_WORD_CLASSES: tuple[tuple[str, frozenset[str]], ...] = (
    ("a determiner", DETERMINERS), ("a possessive", POSSESSIVES), ("a pronoun", PRONOUNS),
    ("a preposition", frozenset(p for p in PREPOSITIONS if " " not in p) | {OF}),
    ("a conjunction", frozenset(w for w in SEPARATOR_WORDS | AND_WORDS if w.isalpha())),
    ("a form of 'be'", BE_WORDS), ("a modal verb", MODALS), ("a question word", WH_WORDS),
    ("a relative pronoun", RELATIVES), ("a number", frozenset(n for n in NUMBERS if " " not in n)))
"""The closed classes of one word, by what a message calls a word of each, from the tables above: words that never
head a verb phrase of a command (hostile32: a frame library's lexical unit "the" read "the cup" as that frame)."""


def function_word_class(word: str) -> str | None:
    """What kind of function word ``word`` is ("a determiner" for "the"), or None for an open-class word."""
    low = word.lower()
    return next((kind for kind, words in FUNCTION_WORD_CLASSES if low in words), None)
